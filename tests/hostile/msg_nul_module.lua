-- a NUL byte inside a module name
-- expect: 1 must be letters, digits
pattern { name = "h", gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = "dk" } }, knitting = "flat" }
cast_on(8)
require "ribs\0/../../etc/passwd"
