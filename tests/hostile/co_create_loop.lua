-- coroutines of 500 instructions each, forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do coroutine.resume(coroutine.create(function() for i = 1, 100 do end end)) end
