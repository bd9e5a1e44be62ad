-- a build whose script fails at its last line writes nothing
-- expect: 1 too long
-- command: build
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
rows(10, "k")
while true do end
