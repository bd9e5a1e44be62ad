-- table.insert at 1 of a "table" of 2^40
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
table.insert(setmetatable({}, { __len = function() return 2^40 end, __index = function() return 1 end, __newindex = function() end }), 1, 0)
