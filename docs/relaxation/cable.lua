-- A close-up for docs/relaxation.md: a 2x2 rope cable (C4F every fourth row) between
-- purl columns, at the seed paper's proportions (loop width 4, loop height 4.2,
-- thickness 2 mm, yarn 1 mm), 8 stitches by 8 rows.
pattern {
  name = "relaxation close-up: cable",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 },
  yarns = { A = { diameter = 1.0, color = "#b7a98f" } },
  knitting = "flat",
}
local cables = require "cables"
cast_on(8)
cables.rope { rows = 8, width = 4, cross = "front", cross_every = 4 }
bind_off()
