-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- A cable crossed on the wrong-side rows of a reverse-stocking-stitch panel, as reversible
-- patterns do: C4B worked from the back shows from the face as purls crossing (2/2 RC
-- purled), and from the back as the knit cable it was worked as.
pattern { name = "wrong-side knit cross", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#8a6f9e" } }, knitting = "flat" }
cast_on(10)
for _ = 1, 3 do
  row "k3, p4, k3"
  row "p3, C4B, p3"
  row "k3, p4, k3"
  row "p3, k4, p3"
end
row "k3, p4, k3"
