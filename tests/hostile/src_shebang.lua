#!/usr/bin/env knitc
-- a first line #!/usr/bin/env knitc, as Lua's own loader allows
-- expect: 0
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
rows(2, "k")
