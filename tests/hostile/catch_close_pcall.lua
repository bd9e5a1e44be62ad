-- a __close that catches the stop with pcall
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local ok = pcall(function()
  local x <close> = setmetatable({}, { __close = function() while true do pcall(function() while true do end end) end end })
  while true do end
end)
while true do end
