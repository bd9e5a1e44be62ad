-- Short rows: a wedge knitted into stocking stitch, as a heel or a dart is shaped. After
-- four plain rows each short row stops one stitch sooner than the one before it and
-- turns, the stitches beyond the turn left on the needle unworked (held), and the next
-- row starts where the yarn turned. Then a row from the last turn to the edge, and the
-- rows go all the way across again: the middle stands twelve rows taller than the edges.
pattern {
  name  = "short_rows",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#b9a27c" } },
  knitting = "flat",
}
local stitches, turns = 24, 6

-- A row of `first` held stitches, `worked` stitches of `stitch`, `last` held, in working order.
local function short_row(first, stitch, worked, last)
  local parts = {}
  if first > 0 then parts[#parts + 1] = "held " .. first end
  parts[#parts + 1] = stitch .. worked
  if last > 0 then parts[#parts + 1] = "held " .. last end
  row(table.concat(parts, ", "))
end

cast_on(stitches)
for _ = 1, 2 do
  row "k"
  row "p"
end
for turn = 1, turns do
  short_row(turn - 1, "k", stitches - 2 * turn + 1, turn) -- right side, from the last turn
  short_row(turn, "p", stitches - 2 * turn, turn)         -- wrong side
end
short_row(turns, "k", stitches - turns, 0)
row "p"
for _ = 1, 3 do
  row "k"
  row "p"
end
bind_off()
