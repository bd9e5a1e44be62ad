-- an error object whose __tostring loops
-- expect: 1 error raised with a table value
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
error(setmetatable({}, { __tostring = function() while true do end end }))
