-- string.rep of the empty string 2^50 times: nothing to copy, so no loop either
-- expect: 0
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
assert(string.rep("", 2^50) == "")
assert(("x"):rep(0) == "")
rows(2, "k")
