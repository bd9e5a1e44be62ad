-- Ribbed cuff swatch, knitted flat: a k1, p1 welt, then k2, p2 rib that starts and ends
-- with k2 on 22 stitches (4 x 5 + 2), from the library's ribs module.
pattern {
  name = "rib",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#8a1c2b" } },
  knitting = "flat",
}
local ribs = require "ribs"

cast_on(22)
ribs.k1p1(4)
ribs.k2p2(16)
bind_off()
