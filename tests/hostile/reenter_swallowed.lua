-- the refused inner pattern{} caught by pcall: the outer one stands
-- expect: 0
local inner = { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" }, B = { weight = "dk" } } }
local yarn = setmetatable({ weight = "dk" }, { __index = function(t, k) pcall(pattern, inner) end })
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = yarn } }
cast_on(10)
rows(4, "k")
assert(not pcall(yarn, "B"))
