-- A mohair swatch: lace-weight mohair knitted loose in stockinette, 16 stitches by 20 rows.
-- Its long hairs make the halo that --section fibres draws (docs/yarn.md, "Fibres").
pattern {
  name = "mohair",
  gauge = { stitches = 20, rows = 28 },
  yarns = { A = { weight = "lace", fibre = "mohair", color = "#b7a3c9" } },
  knitting = "flat",
}
cast_on(16)
for _ = 1, 10 do
  row "k"
  row "p"
end
bind_off()
