-- comparing 4 MiB strings of NUL bytes (strcoll per NUL), forever
-- expect: 1 pattern ran for more than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local a = ("\0"):rep(4 * 1024 * 1024 - 64)
local b = a:sub(1, -2) .. "\1"
local n = 0
while true do if a < b then n = n + 1 end end
