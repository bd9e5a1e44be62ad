-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- A single knit stitch travelling over purls, crossed on the wrong-side rows: T3B and
-- T3F worked from the back show from the face as 1/2 RPC and 1/2 LPC.
pattern { name = "wrong-side crosses", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#4f7a5a" } }, knitting = "flat" }
cast_on(8)
for _ = 1, 2 do
  row "p5, k1, p2"
  row "k2, T3B, k3"
  row "p3, k1, p4"
  row "k2, T3F, k3"
end
row "p5, k1, p2"
