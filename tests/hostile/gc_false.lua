-- even a __gc field of false is refused
-- expect: 1 finalisers are not allowed
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
setmetatable({}, { __gc = false })
