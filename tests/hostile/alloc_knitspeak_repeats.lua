-- a 1.2 KB knitspeak block of Repeat rows 1-99999 (took 1.3 GB)
-- expect: 1 rows
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
knitspeak [[
Row 1: k
Rows 2-99999: Repeat rows 1-99998.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
Repeat rows 1-99999.
]]
