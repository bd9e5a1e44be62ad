-- Reverse stockinette: the purl side is the face. Purl the right-side rows, knit the
-- wrong-side rows.
pattern {
  name = "reverse stockinette",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#b5836b" } },
  knitting = "flat",
}
cast_on(18)
for _ = 1, 10 do
  row "p"
  row "k"
end
bind_off()
