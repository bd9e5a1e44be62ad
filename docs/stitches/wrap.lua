-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Wrapped ribs: two knit-3 ribs on reverse stocking stitch, each wrapped in turn every
-- fourth row (wrap 3: knit 3, wind the yarn twice round them).
pattern { name = "wraps", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#7a9a6a" } }, knitting = "flat" }
cast_on(11)
for _ = 1, 2 do
  row "p2, k3, p1, k3, p2"
  row "k2, p3, k1, p3, k2"
  row "p2, wrap 3, p1, k3, p2"
  row "k2, p3, k1, p3, k2"
  row "p2, k3, p1, wrap 3, p2"
  row "k2, p3, k1, p3, k2"
end
