-- coroutine.wrap in a loop (each new thread under its first hook)
-- expect: 1 too long
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
while true do coroutine.wrap(function() end)() end
