-- an error that reorders itself on screen
-- expect: 1 \u{202e}
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
error("safe \u{202e}txt.exe")
