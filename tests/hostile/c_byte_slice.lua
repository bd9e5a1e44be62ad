-- string.byte of every byte of 4 MiB at once
-- expect: 1 string slice too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("x"):rep(4 * 1024 * 1024 - 64)
local t = { s:byte(1, -1) }
