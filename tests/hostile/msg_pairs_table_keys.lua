-- pairs over table keys, whose order would change from run to run
-- expect: 1 no order
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = { [{}] = 1, [{}] = 2 }
for k, v in pairs(t) do end
