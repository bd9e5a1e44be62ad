-- an __index that indexes itself
-- expect: 1 C stack overflow
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = setmetatable({}, { __index = function(t, k) return t[k] end })
local _ = t.x
