-- A close-up for docs/relaxation.md: plain jersey in DK at a real gauge (22 stitches and
-- 30 rows to 10 cm), 4 stitches by 4 rows, where the relaxed yarns press on each other
-- and their sections flatten (an ellipse across each contact, of the round one's area).
pattern {
  name = "relaxation close-up: pressed sections",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#c9a66b" } },
  knitting = "flat",
}
cast_on(4)
for _ = 1, 2 do
  row "k"
  row "p"
end
