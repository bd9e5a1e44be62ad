-- gsub that writes 100 bytes for every byte
-- expect: 1 string longer than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("x"):rep(100000)
local t = s:gsub(".", ("y"):rep(100))
