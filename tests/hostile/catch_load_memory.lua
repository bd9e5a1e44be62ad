-- load() catching a memory error inside the compiler
-- expect: 1 MiB of memory
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local big = {}
for i = 1, 62 do big[i] = ("x"):rep(4 * 1024 * 1024 - 64 - i) end
local chunk = ("a = { 1, 2, 3 } "):rep(200000)
local f, message = load(chunk)
error("load caught it and returned " .. tostring(message))
