-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Stitches bound off within rows, as an armhole is shaped: three at the start of two
-- rows, then two, each edge stepping in while the stitches between stay in place.
pattern { name = "bound off in rows", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#a05a5a" } }, knitting = "flat" }
cast_on(16)
row "k" row "p" row "k" row "p"
row "BO 3 sts, k to end"
row "BO 3 sts, p to end"
row "BO 2 sts, k to end"
row "BO 2 sts, p to end"
for _ = 1, 3 do
  row "k"
  row "p"
end
