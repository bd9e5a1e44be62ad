-- A close-up for docs/relaxation.md: 1x1 rib in DK at the library's gauge (24 stitches
-- and 30 rows to 10 cm), 14 stitches by 14 rows. Its repeat is found, but tiled it
-- would start the yarns deeper into each other than the layout does, so it relaxes whole.
pattern {
  name = "relaxation close-up: rib",
  gauge = { stitches = 24, rows = 30 },
  yarns = { A = { weight = "dk", color = "#3f6e8c" } },
  knitting = "flat",
}
cast_on(14)
rows(14, "*k1, p1; rep from * to end")
bind_off()
