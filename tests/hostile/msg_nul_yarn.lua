-- a NUL byte inside a yarn name
-- expect: 1 must be a short name
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { ["A\0B"] = { weight = "dk" } } }
