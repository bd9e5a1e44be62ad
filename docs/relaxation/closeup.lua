-- A close-up for docs/relaxation.md: plain jersey at the seed paper's proportions
-- (loop width 4, loop height 4.2, thickness 2 mm, yarn 1 mm), 6 stitches by 6 rows.
pattern {
  name = "relaxation close-up",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 },
  yarns = { A = { diameter = 1.0, color = "#d9c8a9" } },
  knitting = "flat",
}
cast_on(6)
for _ = 1, 3 do
  row "k"
  row "p"
end
bind_off()
