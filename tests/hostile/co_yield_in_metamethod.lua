-- a yield from a verb's metamethod
-- expect: 1 attempt to yield
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local co = coroutine.wrap(function()
  course(setmetatable({}, { __len = function() coroutine.yield() return 1 end }))
end)
co()
