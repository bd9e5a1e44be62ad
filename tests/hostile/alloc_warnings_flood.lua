-- a knitspeak heading skipped a million times
-- expect: 1
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
for i = 1, 1e6 do knitspeak [[
A heading, not a row
Row 1: k
]] end
