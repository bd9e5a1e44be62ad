-- Two 2x2 rope cables (C4F every fourth row) between purl columns, knitted flat.
pattern {
  name = "2x2 cable",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#b7a98f" } },
  knitting = "flat",
}
local cables = require "cables"

cast_on(14)
cables.rope { rows = 20, width = 4, cross = "front", cross_every = 4 }
bind_off()
