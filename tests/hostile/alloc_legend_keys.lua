-- a legend of a hundred thousand symbols
-- expect: 1 keys
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local l = {}
for i = 1, 100000 do l["s" .. i] = "k" end
legend(l)
