-- a __gc finaliser that loops (finalisers run with hooks off, also at close)
-- expect: 1 finalisers are not allowed
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
setmetatable({}, { __gc = function() while true do end end })
