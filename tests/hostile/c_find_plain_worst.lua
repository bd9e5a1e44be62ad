-- a plain find whose every position nearly matches
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("a"):rep(1000000)
local p = ("a"):rep(2000) .. "b"
while true do local _ = s:find(p, 1, true) end
