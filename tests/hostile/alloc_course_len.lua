-- a course{} with a __len of 10^8 and a C __index (grew to gigabytes)
-- expect: 1 a course lists at most
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
course(setmetatable({}, { __len = function() return 1e8 end, __index = type }))
