-- print in an endless loop: the output is bounded
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local line = ("p"):rep(1000)
while true do print(line) end
