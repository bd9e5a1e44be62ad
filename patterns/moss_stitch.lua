-- US moss stitch (UK double moss), on a multiple of 2: two rows of k1, p1, then two of
-- p1, k1.
pattern {
  name = "moss stitch",
  gauge = { stitches = 20, rows = 28 },
  yarns = { A = { weight = "worsted", color = "#4f7a5a" } },
  knitting = "flat",
}
cast_on(18)
for _ = 1, 5 do
  row "*k1, p1; rep from * to end"
  row "*k1, p1; rep from * to end"
  row "*p1, k1; rep from * to end"
  row "*p1, k1; rep from * to end"
end
bind_off()
