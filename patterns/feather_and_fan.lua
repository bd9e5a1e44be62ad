-- Feather and fan (old shale): an 18-stitch repeat of three k2tog, six yarn overs between
-- knits, and three k2tog, every fourth row, over a garter ridge.
pattern {
  name = "feather and fan",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "sport", color = "#9fc5b0" } },
  knitting = "flat",
}
cast_on(20)
row "k"
row "p"
for _ = 1, 4 do
  row "k"
  row "p"
  row "k1, *(k2tog) x3, (yo, k1) x6, (k2tog) x3; rep from * to last st, k1"
  row "k"
end
bind_off()
