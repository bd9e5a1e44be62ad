-- a NUL byte hiding an unknown field
-- expect: 1 unknown field
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, ["knitting\0"] = "flat" }
