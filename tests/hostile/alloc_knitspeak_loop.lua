-- a small knitspeak block worked a million times
-- expect: 1
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
for i = 1, 1e6 do knitspeak [[
Row 1: k
Repeat rows 1-1.
]] end
