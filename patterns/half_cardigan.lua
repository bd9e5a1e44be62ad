-- Half cardigan (half fisherman's rib): a 1x1 rib whose knit stitches are tucked on
-- every wrong-side row, so one face shows plump tuck ribs and the other plain rib.
pattern {
  name = "half cardigan",
  gauge = { stitches = 20, rows = 36 },
  yarns = { A = { weight = "dk", color = "#a34b4b" } },
  knitting = "flat",
}
cast_on(18)
row "*k1, p1; rep from * to end"
for _ = 1, 10 do
  row "*k1, tuck1; rep from * to end"    -- wrong side: the face's knit stitches tucked
  row "*k1, p1; rep from * to end"       -- right side
end
bind_off()
