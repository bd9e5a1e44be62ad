-- an error that would retitle and clear the terminal
-- expect: 1 \x1b
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
error("\27]0;pwned\7\27[2J\27[31mred")
