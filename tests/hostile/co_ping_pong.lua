-- a generator resumed forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local gen = coroutine.wrap(function() while true do coroutine.yield(1) end end)
while true do gen() end
