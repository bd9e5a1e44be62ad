-- a fresh coroutine per try, each stopped and caught
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do coroutine.resume(coroutine.create(function() while true do end end)) end
