-- a warning, then an error: both are printed
-- expect: 1 warning: not a row
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
knitspeak [[
A heading
Row 1: k
]]
row "frobnicate"
