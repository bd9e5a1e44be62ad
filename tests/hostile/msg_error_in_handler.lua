-- an error while handling an error
-- expect: 1
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local t = setmetatable({}, { __index = function(t, k) return t[k] end })
xpcall(function() return t.x end, function(e) return t.y end)
error("after")
