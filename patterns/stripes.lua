-- Horizontal stripes in stockinette: four rows of each colour; each change cuts the old
-- yarn and starts the new one with a tail.
pattern {
  name = "stripes",
  gauge = { stitches = 22, rows = 30 },
  yarns = {
    A = { weight = "dk", color = "#2c4a7a" },
    B = { weight = "dk", color = "#e8dcc0" },
  },
  knitting = "flat",
}
cast_on(18)
for stripe = 1, 5 do
  yarn(stripe % 2 == 1 and "A" or "B")
  row "k"
  row "p"
  row "k"
  row "p"
end
bind_off()
