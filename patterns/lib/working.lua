-- working: the checks and facts the library's modules share while they work rows.
--
--   local working = require "working"
--   working.whole(value, least)     value as a whole number of at least `least`, or nil
--   working.shown(value)            a value as an error message shows it
--   working.rows_problem(name, n)   what is wrong with a row count, or nil
--   working.chart_row()             the next row's number as a chart of the pattern
--                                   counts it: from a right-side row 1
--   working.declare(module, summary, functions)
--                                   declares a module's functions, { { call, what it
--                                   does }, ... }, once: `knitc reference` prints them
--                                   into docs/language.md
--
-- Which side a row is worked from is the runtime's rule alone: right_side().

local working = {}

-- The library's declarations, by module name (working.declare).
working.declared = {}

function working.declare(module, summary, functions)
  working.declared[module] = { summary = summary, functions = functions }
end

local row_number, right_side = row_number, right_side

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

-- The library's rhythms (crossings, lace rows, seed's phase) are a chart's: its row 1 is
-- a right-side row. A piece whose row 1 was worked from the wrong side (a set-up row)
-- starts the chart one row later.
function working.chart_row()
  return row_number() + (right_side(1) and 0 or 1)
end

return working
