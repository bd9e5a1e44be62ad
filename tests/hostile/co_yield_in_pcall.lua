-- a yield through pcall inside a coroutine (it works, as in Lua), forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local co = coroutine.wrap(function() while true do pcall(coroutine.yield, 1) end end)
while true do co() end
