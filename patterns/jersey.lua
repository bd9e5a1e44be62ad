-- Plain jersey (stockinette) swatch, knitted flat: knit the right-side rows, purl the
-- wrong-side rows. The seed paper's plain loop, 20 stitches by 24 rows.
pattern {
  name  = "jersey",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#d9c8a9" } },
  knitting = "flat",
}
cast_on(20)
for _ = 1, 12 do
  row "k"    -- right side
  row "p"    -- wrong side
end
bind_off()
