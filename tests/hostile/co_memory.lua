-- ten million coroutines kept: each is charged its cost, which stops them first
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local keep = {}
for i = 1, 1e7 do keep[i] = coroutine.create(print) end
