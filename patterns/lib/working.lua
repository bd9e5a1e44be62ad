-- working: the checks and facts the library's modules share while they work rows.
--
--   local working = require "working"
--   working.whole(value, least)     value as a whole number of at least `least`, or nil
--   working.shown(value)            a value as an error message shows it
--   working.rows_problem(name, n)   what is wrong with a row count, or nil
--   working.wrong_side()            true when the next row is worked from the wrong side

local working = {}

local knitting, row_number = knitting, row_number

function working.whole(value, least)
  if type(value) ~= "number" then return nil end
  local n = math.tointeger(value)
  if n == nil or n < least then return nil end
  return n
end

function working.shown(value)
  if type(value) == "number" or value == nil then return tostring(value) end
  if type(value) == "string" then return ("%q"):format(value) end
  return "a " .. type(value)
end

function working.rows_problem(name, rows)
  if working.whole(rows, 1) then return nil end
  return name .. ": rows must be a whole number from 1 up, not " .. working.shown(rows)
end

-- Flat knitting, an even row.
function working.wrong_side()
  return knitting() == "flat" and row_number() % 2 == 0
end

return working
