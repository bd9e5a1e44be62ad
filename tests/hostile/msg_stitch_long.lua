-- a row of one 1 MB word
-- expect: 1 bytes
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
row(("k"):rep(1000000))
