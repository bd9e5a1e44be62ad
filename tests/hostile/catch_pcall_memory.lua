-- pcall catching the memory cap, then growing again
-- expect: 1 MiB of memory
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local keep = {}
while true do
  pcall(function() local t = {} while true do t[#t + 1] = {} end end)
  keep[#keep + 1] = {}
end
