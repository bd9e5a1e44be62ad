-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Stockinette between a chain selvedge (left and right) and a garter one would be
-- the default; the edge stitch slipped at the start of every row spans two rows.
pattern { name = "chain selvedge", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#b0603a" } }, knitting = "flat", selvedge = "chain" }
cast_on(8)
for _ = 1, 5 do
  row "edge st, k6, edge st"
  row "edge st, p6, edge st"
end
