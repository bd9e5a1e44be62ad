-- table.unpack of ten million values
-- expect: 1 too many results to unpack
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = { table.unpack({}, 1, 1e7) }
