-- A small jersey swatch in a red and blue heather, half and half: for the browser test of
-- the baked textures (tests/yarn/textures.mjs), whose colour map carries the fibres' colours.
pattern {
  name  = "heather swatch",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, heather = { {"#c0282d", 1}, {"#2848c0", 1} } } },
  knitting = "flat",
}
cast_on(10)
for _ = 1, 5 do
  row "k"
  row "p"
end
bind_off()
