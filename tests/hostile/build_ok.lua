-- a build that works writes its file (and nothing else)
-- expect: 0
-- command: build
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
rows(4, "k")
