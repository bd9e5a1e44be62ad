-- an error message of 4 MiB
-- expect: 1 bytes
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
error(("x"):rep(4 * 1024 * 1024 - 64))
