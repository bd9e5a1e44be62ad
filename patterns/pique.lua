-- Single pique: stockinette with a tuck on every other stitch of every right-side row,
-- the tucks staggered, so the face is a fine honeycomb of held loops.
pattern {
  name = "pique",
  gauge = { stitches = 22, rows = 34 },
  yarns = { A = { weight = "sport", color = "#e6e1d3" } },
  knitting = "flat",
}
cast_on(18)
for _ = 1, 5 do
  row "*k1, tuck1; rep from * to end"
  row "p"
  row "*tuck1, k1; rep from * to end"
  row "p"
end
bind_off()
