-- s = s .. s until it cannot be
-- expect: 1 string longer than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = "x"
while true do s = s .. s end
