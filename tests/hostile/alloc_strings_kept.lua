-- a hundred 4 MiB strings kept
-- expect: 1 MiB of memory
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local keep = {}
for i = 1, 100 do keep[i] = ("x"):rep(4 * 1024 * 1024 - 64 - i) end
