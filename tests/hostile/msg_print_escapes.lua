-- print of escape sequences
-- expect: 0 \x1b
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
print("\27[2J\27]0;title\7")
rows(2, "k")
