-- gsub of ".-.-.-.-b" over 5000 a
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("a"):rep(5000)
local _ = s:gsub(".-.-.-.-b", "")
