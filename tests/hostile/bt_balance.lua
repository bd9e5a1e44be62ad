-- %b() over a 4 MiB run of open brackets, forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("("):rep(4 * 1024 * 1024 - 64)
while true do local _ = s:find("%b()") end
