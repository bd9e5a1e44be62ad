-- Plain jersey (stockinette) swatch: the seed paper's plain loop, 20 stitches by 24 rows.
pattern {
  name  = "jersey",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#d9c8a9" } },
}
cast_on(20)
rows(24, "k")
