-- Twisted 1x1 rib, flat: every knit and purl worked through the back loop, so each
-- column of knits stands as a row of crossed loops (Stitch Maps' "Twisted Rib").
pattern {
  name = "twisted rib",
  gauge = { stitches = 24, rows = 30 },
  yarns = { A = { diameter = 1.0, color = "#7a4b8c" } },
  knitting = "flat",
}
cast_on(17)
knitspeak [[
  Row 1 (RS): K1 tbl, *p1 tbl, k1 tbl; repeat from *.
  Row 2: P1 tbl, *k1 tbl, p1 tbl; repeat from *.
]]
for _ = 1, 7 do
  knitspeak [[
    Row 1: K1 tbl, *p1 tbl, k1 tbl; repeat from *.
    Row 2: P1 tbl, *k1 tbl, p1 tbl; repeat from *.
  ]]
end
bind_off()
