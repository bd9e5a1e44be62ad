-- xpcall whose handler loops forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
xpcall(error, function() while true do end end)
while true do end
