-- a frontier pattern tried at every position, forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("a"):rep(1000000)
while true do local _ = s:find("%f[%z]a") end
