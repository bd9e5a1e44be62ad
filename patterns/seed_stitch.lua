-- Seed stitch (UK moss) on an odd count: every row k1, p1, ending k1, so each stitch is
-- knit over purl and purl over knit.
pattern {
  name = "seed stitch",
  gauge = { stitches = 20, rows = 28 },
  yarns = { A = { weight = "worsted", color = "#8c5a3f" } },
  knitting = "flat",
}
cast_on(17)
rows(20, "*k1, p1; rep from * to last st, k1")
bind_off()
