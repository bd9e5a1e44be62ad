-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Quilted lattice (Barbara Walker's, a multiple of 6 + 3): floats slipped with the yarn
-- in front on one right-side row are caught by a knit worked under them two rows up,
-- the next set half a repeat over, so the lifted floats make a lattice.
pattern { name = "quilted lattice", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#6a7fa8" } }, knitting = "flat" }
cast_on(15)
row "k"
row "p"
for _ = 1, 2 do
  row "k2, *sl5 wyif, k1; rep from * to last st, k1"
  row "p"
  row "k4, k under float, k5, k under float, k4"
  row "p"
  row "k1, sl3 wyif, k1, sl5 wyif, k1, sl3 wyif, k1"
  row "p"
  row "k1, k under float, k5, k under float, k5, k under float, k1"
  row "p"
end
row "k"
