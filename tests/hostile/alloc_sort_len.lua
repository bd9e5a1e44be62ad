-- table.sort over a __len of 2^30
-- expect: 1
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
table.sort(setmetatable({}, { __len = function() return 2^30 end, __index = function() return 1 end, __newindex = function() end }))
