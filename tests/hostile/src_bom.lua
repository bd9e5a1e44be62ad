-- a file that starts with a UTF-8 byte order mark
-- expect: 0
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
rows(2, "k")
