-- find with ("a*"):rep(40) .. "b"
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("a"):rep(40)
local _ = s:find(("a*"):rep(40) .. "b")
