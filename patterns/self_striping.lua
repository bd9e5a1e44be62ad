-- A self-striping yarn (50 cm red, 50 cm cream, repeated) on a narrow tube: a mitten's
-- thumb of 12 stitches. A round takes about 24 cm of yarn, so each colour lasts about two
-- rounds: narrow stripes, all the way round. The same yarn pools on a wider tube
-- (self_striping_pooled.lua).
pattern {
  name = "self-striping",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", colors = { { "#b5302a", 50 }, { "#efe6d2", 50 } } } },
  knitting = "round",
}
cast_on(12)
rows(30, "k")
bind_off()
