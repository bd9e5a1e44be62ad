-- coroutines inside coroutines, 300 deep
-- expect: 1 C stack overflow
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local function dive(n) return coroutine.wrap(function() return dive(n + 1) end)() end
dive(1)
