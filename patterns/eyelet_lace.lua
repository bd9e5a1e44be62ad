-- Eyelet lace: a yarn over and a k2tog every fourth stitch, every fourth row, the
-- eyelets staggered by two stitches.
pattern {
  name = "eyelet lace",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#e3b7c8" } },
  knitting = "flat",
}
cast_on(18)
row "k"
row "p"
for _ = 1, 3 do
  row "k1, *k2, yo, k2tog; rep from * to last st, k1"
  row "p"
  row "k"
  row "p"
  row "k1, *yo, k2tog, k2; rep from * to last st, k1"
  row "p"
  row "k"
  row "p"
end
bind_off()
