-- compiling a chunk over and over
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local chunk = ("x = 1 "):rep(2000)
while true do load(chunk) end
