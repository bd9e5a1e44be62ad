-- a course{} whose __index works another course
-- expect: 1 was called while course was still running
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
course(setmetatable({}, { __len = function() return 8 end, __index = function() course { "k" } return "k" end }))
