-- a course{} item of 4 MiB
-- expect: 1 give one stitch per item
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local big = ("k"):rep(4 * 1024 * 1024 - 64)
course(setmetatable({}, { __len = function() return 99999 end, __index = function(t, i) if i == "rep" or i == "yarn" then return nil end return big end }))
