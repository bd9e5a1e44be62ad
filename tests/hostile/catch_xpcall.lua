-- xpcall with a handler that swallows the error
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do xpcall(function() while true do end end, function(e) return e end) end
