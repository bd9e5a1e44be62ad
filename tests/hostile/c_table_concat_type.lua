-- table.concat over 2^40 entries made by type()
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = setmetatable({}, { __len = function() return 2^40 end, __index = type })
local s = table.concat(t)
