-- coroutine.yield outside any coroutine
-- expect: 1 attempt to yield from outside a coroutine
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
coroutine.yield(1)
