-- next() over a table of a million empty slots, forever
-- expect: 1 pattern ran for more than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = {}
for i = 1, 1000000 do t[i] = i end
for i = 1, 1000000 do t[i] = nil end
t.x = 1
while true do local _ = next(t) end
