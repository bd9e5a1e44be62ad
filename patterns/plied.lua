-- A close-up of plied yarn: three plies twisted S, as most knitting yarns are plied.
pattern {
  name  = "plied",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#b5523b", section = "plied", plies = 3, twist = 30, direction = "S" } },
}
cast_on(6)
rows(6, "k")
