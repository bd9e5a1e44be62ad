-- Two-colour stranded colourwork: a checked band and a zigzag in two yarns, knitted in
-- flat, so that the back shows the yarn not in use floating behind the stitches of the other.
pattern {
  name = "stranded colourwork",
  gauge = { stitches = 26, rows = 28 },
  yarns = {
    A = { weight = "sport", color = "#f2ead8" },
    B = { weight = "sport", color = "#8a2331" },
  },
  knitting = "flat",
}
cast_on(24)
row "k"
row "p"
legend { ["."] = "k", ["#"] = { "k", yarn = "B" } }
chart [[
..#...#...#.
.#.#.#.#.#.#
#...#...#...
............
##..##..##..
##..##..##..
..##..##..##
..##..##..##
]]
row "k"
row "p"
bind_off()
