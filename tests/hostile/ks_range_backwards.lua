-- a knitspeak range that runs backwards
-- expect: 1 runs backwards
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
knitspeak [[
Row 1: k
Rows 5-2: p
]]
