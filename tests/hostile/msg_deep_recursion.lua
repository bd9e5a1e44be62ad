-- recursion without end
-- expect: 1 stack overflow
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local function f(n) return 1 + f(n + 1) end
f(1)
