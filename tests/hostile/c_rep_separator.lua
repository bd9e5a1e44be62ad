-- string.rep with a separator to a petabyte
-- expect: 1 string longer than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = string.rep("x", 2^40, ",")
