-- working: how the library's modules declare their functions, and the facts they share
-- while they work rows.
--
--   local working = require "working"
--   working.declare(module, summary)   a module, with one line on what it holds
--   module.f = working.define(module, { name = "f", doc = "...", args = { ... } or
--     fields = { ... }, work = function(...) ... end })
--                                   a function, declared once: its arguments (or the
--                                   fields of the one table it takes) are checked from
--                                   the declaration before `work` runs, with the
--                                   defaults filled in, and `knitc reference` prints the
--                                   same declaration into docs/language.md. `work`
--                                   returns nil, or what is wrong (before working
--                                   anything): an error at the line that called f.
--   working.chart_row()             the next row's number as a chart of the pattern
--                                   counts it: from a right-side row 1
--
-- An argument is { "name", "whole", least = n } (a whole number from n up), { "name",
-- "whole", values = { 2, 4 } } (one of those), or { "name", "choice", choices = { "a",
-- "b" } }; with default = v, or optional = true (work then gets nil and decides; say
-- what it decides in default_doc), and doc = "one line".
--
-- Which side a row is worked from is the runtime's rule alone: right_side().

local working = {}

-- The library's declarations, by module name: { summary = ..., functions = { { call =
-- "m.f(a, b)", doc = ..., args = { { name, takes, default, doc }, ... } (as the reference
-- prints them), declaration = the arguments as declared }, ... } }.
working.declared = {}

local row_number, right_side = row_number, right_side

function working.declare(module, summary)
  working.declared[module] = { summary = summary, functions = {} }
end

local function shown(value)
  if type(value) == "number" or value == nil then return tostring(value) end
  if type(value) == "string" then return ("%q"):format(value) end
  return "a " .. type(value)
end

-- What an argument takes, as its error message and the reference say it.
local function takes(arg)
  local kind = arg[2]
  if kind == "whole" and arg.values then
    local texts = {}
    for i, v in ipairs(arg.values) do texts[i] = tostring(v) end
    return table.concat(texts, ", ", 1, #texts - 1) .. " or " .. texts[#texts]
  elseif kind == "whole" then
    return ("a whole number from %d up"):format(arg.least)
  elseif kind == "choice" then
    local texts = {}
    for i, v in ipairs(arg.choices) do texts[i] = ("%q"):format(v) end
    return table.concat(texts, ", ", 1, #texts - 1) .. " or " .. texts[#texts]
  end
  error("working.define: argument " .. tostring(arg[1]) .. " has no kind 'whole' or 'choice'", 3)
end

-- The value an argument gets: the checked value or its default; nil and what is wrong.
local function checked(arg, value)
  if value == nil then
    if arg.default ~= nil or arg.optional then return arg.default end
  elseif arg[2] == "whole" and type(value) == "number" then
    local n = math.tointeger(value)
    if n and (arg.least == nil or n >= arg.least) then
      if not arg.values then return n end
      for _, v in ipairs(arg.values) do
        if v == n then return n end
      end
    end
  elseif arg[2] == "choice" then
    for _, v in ipairs(arg.choices) do
      if v == value then return value end
    end
  end
  return nil, arg[1] .. " must be " .. takes(arg) .. ", not " .. shown(value)
end

-- The fields of t that `args` does not declare, sorted, as one string; nil if none.
-- (Sorted: the order pairs() visits them in never reaches a message.)
local function unknown_fields(t, args)
  local known, unknown = {}, {}
  for _, arg in ipairs(args) do known[arg[1]] = true end
  for key in pairs(t) do
    if not known[key] then unknown[#unknown + 1] = type(key) == "string" and key or "[" .. shown(key) .. "]" end
  end
  if #unknown == 0 then return nil end
  table.sort(unknown)
  return table.concat(unknown, ", ")
end

-- The declared argument list's values from a call's: (name, checked values) or raises.
local function read_arguments(name, spec, ...)
  local args, values = spec.args or spec.fields, {}
  if spec.fields then
    local t = ...
    if type(t) ~= "table" then
      error(("%s takes a table, e.g. %s{ %s = 12 }, not %s"):format(name, name, args[1][1], shown(t)), 3)
    end
    local unknown = unknown_fields(t, args)
    if unknown then
      local names = {}
      for i, arg in ipairs(args) do names[i] = arg[1] end
      table.sort(names)
      error(name .. ": unknown field(s) " .. unknown .. "; known fields: " .. table.concat(names, ", "), 3)
    end
    for i, arg in ipairs(args) do
      local v, problem = checked(arg, t[arg[1]])
      if problem then error(name .. ": " .. problem, 3) end
      values[i] = v
    end
  else
    local given = { ... }
    for i, arg in ipairs(args) do
      local v, problem = checked(arg, given[i])
      if problem then error(name .. ": " .. problem, 3) end
      values[i] = v
    end
  end
  return values, #args
end

-- The call as the reference shows it: m.f(a, [b]) or m.f{ a, b }.
local function call_text(name, spec)
  local parts = {}
  for i, arg in ipairs(spec.args or spec.fields) do
    local optional = spec.args and (arg.default ~= nil or arg.optional)
    parts[i] = optional and "[" .. arg[1] .. "]" or arg[1]
  end
  if spec.fields then return name .. "{ " .. table.concat(parts, ", ") .. " }" end
  return name .. "(" .. table.concat(parts, ", ") .. ")"
end

function working.define(module, spec)
  local declared = working.declared[module]
  assert(declared, "working.define: declare the module first (working.declare)")
  assert(type(spec.work) == "function" and (spec.args == nil) ~= (spec.fields == nil),
    "working.define: a function needs work and either args or fields")
  local name = module .. "." .. spec.name
  local reference = { call = call_text(name, spec), doc = spec.doc, args = {}, declaration = spec.args or spec.fields }
  for i, arg in ipairs(spec.args or spec.fields) do
    local default = arg.default_doc or (arg.default ~= nil and shown(arg.default)) or "-"
    reference.args[i] = { arg[1], takes(arg), default, arg.doc or "" }
  end
  declared.functions[#declared.functions + 1] = reference
  local work, unpack = spec.work, table.unpack
  return function(...)
    local values, n = read_arguments(name, spec, ...)
    local problem = work(unpack(values, 1, n))
    if problem then error(problem, 2) end
  end
end

-- The library's rhythms (crossings, lace rows, seed's phase) are a chart's: its row 1 is
-- a right-side row. A piece whose row 1 was worked from the wrong side (a set-up row)
-- starts the chart one row later.
function working.chart_row()
  return row_number() + (right_side(1) and 0 or 1)
end

return working
