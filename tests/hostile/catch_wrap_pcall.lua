-- pcall around coroutine.wrap
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do pcall(coroutine.wrap(function() while true do end end)) end
