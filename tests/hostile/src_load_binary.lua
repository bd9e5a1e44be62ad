-- a binary chunk through load()
-- expect: 1 attempt to load a binary chunk
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
local f, e = load("\27Lua")
error(e)
