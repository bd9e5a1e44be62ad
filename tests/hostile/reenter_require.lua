-- require from a metamethod inside a verb
-- expect: 1 was called while course was still running
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
course(setmetatable({ "k" }, { __len = function() require "ribs" return 1 end }))
