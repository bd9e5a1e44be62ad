-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Two ladders: a yarn over on row 1 makes each dropped stitch's wale, and row 8 drops it,
-- so the wale unravels back to the yarn over into a ladder of straight rungs.
pattern { name = "drop stitch", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#b0685a" } }, knitting = "flat" }
cast_on(10)
row "k3, yo, k4, yo, k3"
row "p"
for _ = 1, 3 do
  row "k"
  row "p"
end
row "k3, drop, k4, drop, k3"
row "p"
row "k"
row "p"
