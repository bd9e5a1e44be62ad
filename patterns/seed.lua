-- Texture sampler, knitted flat on an odd count: garter borders around a band of seed
-- stitch (UK moss) and a band of US moss stitch (UK double moss), from the ribs module.
pattern {
  name = "seed",
  gauge = { stitches = 20, rows = 28 },
  yarns = { A = { weight = "worsted", color = "#5b7f4a" } },
  knitting = "flat",
}
local ribs = require "ribs"

cast_on(21)
ribs.garter(4)
ribs.seed(10)
ribs.moss(8)
ribs.garter(4)
bind_off()
