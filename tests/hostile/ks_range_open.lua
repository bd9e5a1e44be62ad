-- a knitspeak range with no end (was dropped with a warning)
-- expect: 1 has no last row
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
knitspeak [[
Row 1: k
Rows 2-: p
]]
