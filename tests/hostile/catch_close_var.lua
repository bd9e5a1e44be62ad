-- a to-be-closed variable whose __close loops
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
do
  local x <close> = setmetatable({}, { __close = function() while true do end end })
end
