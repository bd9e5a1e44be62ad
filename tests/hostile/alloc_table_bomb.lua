-- a table that grows without end
-- expect: 1 MiB of memory
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = {}
while true do t[#t + 1] = { 1, 2, 3 } end
