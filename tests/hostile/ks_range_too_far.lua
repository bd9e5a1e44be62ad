-- a knitspeak range past row 100000 (was dropped with a warning)
-- expect: 1 past row 100000
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
knitspeak [[
Row 1: k
Rows 2-100000000: p
]]
