-- table.concat over a __len of 2^60 with a C __index
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = setmetatable({}, { __len = function() return 2^60 end, __index = function() return "" end })
local s = table.concat(t)
