-- tonumber over 4 MiB of spaces, forever (no allocation, no hook in the call)
-- expect: 1 pattern ran for more than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = (" "):rep(4 * 1024 * 1024 - 64)
while true do local _ = tonumber(s) end
