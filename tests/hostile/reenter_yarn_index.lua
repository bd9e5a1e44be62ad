-- a yarn table whose __index calls pattern{} again (was a heap overflow)
-- expect: 1 was called while pattern was still running
local inner = { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" }, B = { weight = "dk" }, C = { weight = "dk" } } }
local yarn = setmetatable({ weight = "dk" }, { __index = function(t, k) pattern(inner) end })
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = yarn } }
cast_on(10)
rows(4, "k")
