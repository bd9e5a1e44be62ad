-- Slip-stitch honeycomb: every other stitch slipped for two rows with the yarn on the
-- wrong side, the slipped stitches staggered every four rows; the floats lie on the back.
pattern {
  name = "slip-stitch honeycomb",
  gauge = { stitches = 22, rows = 32 },
  yarns = { A = { weight = "dk", color = "#d08a2e" } },
  knitting = "flat",
}
cast_on(18)
row "k"
row "p"
for _ = 1, 4 do
  row "*k1, sl1 wyib; rep from * to end"
  row "*sl1 wyif, p1; rep from * to end"
  row "k"
  row "p"
  row "*sl1 wyib, k1; rep from * to end"
  row "*p1, sl1 wyif; rep from * to end"
  row "k"
  row "p"
end
bind_off()
