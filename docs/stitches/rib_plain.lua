-- A close-up for docs/stitches.md: drawn with knitc render --side face --size 700x500.
pattern { name = "1x1 rib", gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0, color = "#7a4b8c" } }, knitting = "flat" }
cast_on(7)
rows(6, "k1, *p1, k1; rep from *")
