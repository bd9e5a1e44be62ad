-- a NUL byte inside a row's text is not the end of it
-- expect: 1 \x00
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
row("k\0p")
