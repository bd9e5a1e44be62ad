-- the standard library's ways out are gone
-- expect: 1 attempt to
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local ways = { io, os, debug, package, dofile, loadfile, collectgarbage, string.dump, string.pack }
for _, w in pairs(ways) do error("found one") end
io.open("/etc/passwd")
