-- Garter stitch: knit every row, flat. Ridges of purl bumps on both sides.
pattern {
  name = "garter",
  gauge = { stitches = 20, rows = 40 },
  yarns = { A = { weight = "worsted", color = "#c7a548" } },
  knitting = "flat",
}
cast_on(18)
rows(24, "k")
bind_off()
