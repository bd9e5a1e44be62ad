-- A close-up for docs/relaxation.md: half cardigan (the knit stitches of a 1x1 rib
-- tucked on every wrong-side row) at the seed paper's proportions, 8 stitches by 8 rows.
pattern {
  name = "relaxation close-up: tuck",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 },
  yarns = { A = { diameter = 1.0, color = "#a34b4b" } },
  knitting = "flat",
}
cast_on(8)
row "*k1, p1; rep from *"
for _ = 1, 4 do
  row "*k1, tuck1; rep from *"
  row "*k1, p1; rep from *"
end
bind_off()
