-- the string metatable's __index looping
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
getmetatable("").__index = function() while true do end end
local _ = ("x"):upper()
