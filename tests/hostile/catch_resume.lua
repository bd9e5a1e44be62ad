-- coroutine.resume catching the limit
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local co = coroutine.create(function() while true do end end)
while true do coroutine.resume(co) end
