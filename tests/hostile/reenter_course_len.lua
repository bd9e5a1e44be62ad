-- a course{} whose __len works rows
-- expect: 1 was called while course was still running
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
course(setmetatable({ "k" }, { __len = function() rows(2, "k") return 1 end }))
