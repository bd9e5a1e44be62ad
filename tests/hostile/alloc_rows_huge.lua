-- a hundred thousand stitches, a hundred thousand rows
-- expect: 1
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } } }
cast_on(100000)
rows(100000, "k")
