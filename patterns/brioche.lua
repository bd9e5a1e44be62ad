-- Brioche stockinette, flat: every other stitch knitted (or purled) into the stitch
-- below, so each dropped loop lies on the one worked into it, as in fisherman's rib.
pattern {
  name = "brioche",
  gauge = { stitches = 22, rows = 40 },
  yarns = { A = { diameter = 1.0, color = "#4f7f5a" } },
  knitting = "flat",
}
cast_on(16)
rows(2, "k")
for _ = 1, 8 do
  knitspeak [[
    Row 1 (RS): *K1 below, k1, repeat from *.
    Row 2: *P1 below, p1, repeat from *.
  ]]
end
bind_off()
