-- A sweater front's size in plain jersey: 150 stitches by 250 rows at the seed paper's
-- proportions (about 59 x 75 cm), knitted flat and bound off. The garment-scale fabric of
-- the benchmark and the browser test (docs/performance.md).
pattern {
  name  = "sweater_front",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#d9c8a9" } },
  knitting = "flat",
}
cast_on(150)
for _ = 1, 125 do
  row "k"    -- right side
  row "p"    -- wrong side
end
bind_off()
