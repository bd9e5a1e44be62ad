-- string.rep of 3 MiB, made and dropped forever
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do local _ = ("ab"):rep(1500000) end
