-- The yarn of self_striping.lua (50 cm red, 50 cm cream) on a tube of 48 stitches. A
-- round takes about 96 cm, just short of the 100 cm the two colours repeat in, so each
-- colour lands where it was a round before, 4 cm (two stitches) further back: the colours
-- pool into a spiral, as knitters see on a sock leg of the "wrong" width.
pattern {
  name = "self-striping, pooled",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", colors = { { "#b5302a", 50 }, { "#efe6d2", 50 } } } },
  knitting = "round",
}
cast_on(48)
rows(24, "k")
bind_off()
