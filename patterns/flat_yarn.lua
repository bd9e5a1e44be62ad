-- Stockinette in a flattened yarn (a tape or a yarn pressed flat: half as thick as wide).
pattern {
  name  = "flat yarn",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, -- mm
  yarns = { A = { diameter = 1.0, color = "#3b7fb5", section = "ellipse", aspect = 0.5 } },
}
cast_on(8)
rows(8, "k")
