-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Nupps staggered in stocking stitch, as Estonian lace sets them: five loops worked into
-- one stitch on a right-side row, purled together on the next.
pattern { name = "nupps", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#c9b27c" } }, knitting = "flat" }
cast_on(11)
row "k"
row "p"
for _ = 1, 2 do
  row "k3, nupp, k7"
  row "p7, p5tog, p3"
  row "k"
  row "p"
  row "k7, nupp, k3"
  row "p3, p5tog, p7"
  row "k"
  row "p"
end
