-- 1x1 rib, flat on an even count: k1, p1 across every row, the knits over the knits.
pattern {
  name = "1x1 rib",
  gauge = { stitches = 24, rows = 30 },
  yarns = { A = { weight = "dk", color = "#3f6e8c" } },
  knitting = "flat",
}
cast_on(18)
rows(20, "*k1, p1; rep from * to end")
bind_off()
