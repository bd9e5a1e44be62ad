-- a legend whose symbol table works a chart
-- expect: 1 was called while legend was still running
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
legend(setmetatable({ ["#"] = "k" }, { __index = function() chart [[
#
]] end }))
legend { ["#"] = setmetatable({}, { __index = function() chart [[
#
]] end }) }
