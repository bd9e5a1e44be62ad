-- string.format gluing 4 MiB strings
-- expect: 1 string longer than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("x"):rep(3 * 1024 * 1024)
local t = string.format("%s%s", s, s)
