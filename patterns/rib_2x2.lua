-- 2x2 rib, flat on a multiple of 4 plus 2: the wrong-side rows start with p2.
pattern {
  name = "2x2 rib",
  gauge = { stitches = 24, rows = 30 },
  yarns = { A = { weight = "dk", color = "#6b4e8c" } },
  knitting = "flat",
}
cast_on(18)
for _ = 1, 10 do
  row "k2, *p2, k2; rep from * to end"   -- right side
  row "p2, *k2, p2; rep from * to end"   -- wrong side
end
bind_off()
