-- Stockinette knitted in the round: every round knit, the yarn one spiral round a tube
-- of 24 stitches, 16 rounds.
pattern {
  name  = "jersey in the round",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#7d9bb5" } },
  knitting = "round",
}
cast_on(24)
rows(16, "k")
bind_off()
