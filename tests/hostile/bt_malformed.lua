-- a malformed pattern is an ordinary error
-- expect: 1 malformed pattern
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local _ = ("abc"):find("[a")
