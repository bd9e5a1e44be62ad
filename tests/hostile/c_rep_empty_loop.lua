-- string.rep of nothing in an endless loop
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do local _ = string.rep("", 2^50, "") end
