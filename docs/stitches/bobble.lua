-- A close-up for docs/stitches.md: drawn with knitc render --side both --size 640x520.
-- Bobbles on reverse stocking stitch, as Aran patterns set them: MB (five loops in one
-- stitch, turned and worked three rows more, gathered) on a right-side row.
pattern { name = "bobbles", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#c9b27c" } }, knitting = "flat" }
cast_on(11)
row "p"
row "k"
row "p5, MB, p5"
row "k"
row "p"
row "k"
row "p2, MB, p5, MB, p2"
row "k"
row "p"
row "k"
