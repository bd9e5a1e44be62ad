-- a __gc reached only through __index is not a finaliser
-- expect: 0
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
setmetatable({}, setmetatable({}, { __index = { __gc = function() while true do end end } }))
rows(2, "k")
