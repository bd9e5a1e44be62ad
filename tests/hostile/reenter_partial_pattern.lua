-- a pattern{} that fails half-way, caught, leaves no yarns behind
-- expect: 1 yarn 'B' was never declared
pcall(pattern, { gauge = { stitches = 22, rows = "x" }, yarns = { A = { weight = "dk" }, B = { weight = "dk" } } })
pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } } }
cast_on(10)
rows(4, "k")
yarn "B"
