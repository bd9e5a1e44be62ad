-- Full cardigan (fisherman's rib as the knitting machine makes it): a 1x1 rib tucked on
-- every row, the knit stitches on wrong-side rows, the purl stitches on right-side rows.
pattern {
  name = "full cardigan",
  gauge = { stitches = 20, rows = 40 },
  yarns = { A = { weight = "dk", color = "#3c7f7a" } },
  knitting = "flat",
}
cast_on(18)
row "*k1, p1; rep from * to end"
for _ = 1, 10 do
  row "*k1, tuck1; rep from * to end"    -- wrong side: the face's knit stitches tucked
  row "*k1, tuck1; rep from * to end"    -- right side: the purl stitches tucked
end
bind_off()
