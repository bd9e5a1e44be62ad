-- utf8.len over 4 MiB, forever
-- expect: 1 pattern ran for more than
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local s = ("\u{e9}"):rep(2 * 1024 * 1024 - 64)
while true do local _ = utf8.len(s) end
