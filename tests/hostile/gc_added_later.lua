-- __gc added after setmetatable marks nothing: the script runs
-- expect: 0
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local mt = {}
local t = setmetatable({}, mt)
mt.__gc = function() while true do end end
rows(2, "k")
