-- a back-reference tried at every split
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("ab"):rep(20000)
local _ = s:find("(.-)%1%1c")
