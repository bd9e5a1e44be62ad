-- _ENV swapped for a table whose __index loops
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local _ENV = setmetatable({}, { __index = function() while true do end end })
rows(2, "k")
