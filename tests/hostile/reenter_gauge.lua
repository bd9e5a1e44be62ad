-- a gauge whose __index casts on
-- expect: 1 was called while pattern was still running
pattern { gauge = setmetatable({ stitches = 22 }, { __index = function() cast_on(4) return 30 end }), yarns = { A = { weight = "dk" } } }
cast_on(4)
rows(2, "k")
