-- Plated jersey: two yarns knitted together into every loop, the second on the loops'
-- technical face, so the face shows one colour and the back the other. On a machine the
-- two are fed by two carriers at once (`knitc knitout` writes each stitch with both).
pattern {
  name = "plated",
  gauge = { stitches = 22, rows = 30 },
  yarns = {
    A = { weight = "fingering", color = "#e8dcc0" },  -- the ground: shows on the back
    B = { weight = "fingering", color = "#8a1c2b" },  -- the plating yarn: shows on the face
  },
  knitting = "flat",
}
cast_on(16)
yarn("A", "B")
for _ = 1, 8 do
  row "k"  -- right side
  row "p"  -- wrong side
end
yarn "A"  -- the bind-off in the ground alone
bind_off()
