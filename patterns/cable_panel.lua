-- Two 6-stitch rope cables crossed to the right (C6B) every 6 rows between purl columns,
-- knitted flat above and below k2, p2 rib: 18 stitches = (6 + 2) x 2 + 2.
pattern {
  name = "cable panel",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#c9b79c" } },
  knitting = "flat",
}
local ribs = require "ribs"
local cables = require "cables"

cast_on(18)
ribs.k2p2(6)
cables.rope { rows = 18, width = 6, cross = "back", cross_every = 6 }
ribs.k2p2(4)
bind_off()
