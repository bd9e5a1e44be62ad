-- cables: cable panels as functions that work rows.
--
--   local cables = require "cables"
--
-- The functions are declared below (working.declare), and docs/language.md lists them.
--
-- Only rows is required. The panel repeats across all the live stitches, and the cables
-- cross on rows cross_every - 1, 2 * cross_every - 1, ... of the whole piece as a chart
-- counts them (working.chart_row: its row 1 is a right-side row), so a panel continued by
-- a second call keeps its rhythm. In flat knitting cross_every must be even: the
-- crossings then fall on right-side rows, and the wrong-side rows are written k over the
-- purls and p over the cables.
-- The functions return nothing. A bad argument is an error at the line that called them.

local cables = {}

local row, live, knitting, right_side = row, live, knitting, right_side
local working = require "working"
local whole, shown, rows_problem, chart_row = working.whole, working.shown, working.rows_problem, working.chart_row

working.declare("cables", "cable panels", {
  { "cables.rope{ rows = M, width = 4, cross = \"front\", cross_every = 4, purl_border = 2 }",
    "a rope cable: width knit stitches (2, 4, 6 or 8) crossed half over half with C<width>F (cross = \"front\", the "
    .. "front half moves left) or C<width>B (\"back\", it moves right) every cross_every rows (default: the width), "
    .. "with purl_border purl stitches (default 2, may be 0) between and beside the cables. Stitches: a multiple of "
    .. "width + purl_border, plus purl_border; e.g. 14 for two 4-stitch ropes with 2 purls around each" },
  { "cables.horseshoe{ rows = M, width = 8, cross_every = 4, purl_border = 2 }",
    "a horseshoe cable: width knit stitches (4, 8, 12 or 16); the crossing row works the right half C<half>B and the "
    .. "left half C<half>F, so the stitches part from the centre. cross_every defaults to half the width. Stitches as "
    .. "for rope" },
})

-- The fields of args that the list `known` does not name, sorted, as one string; nil if
-- none. (Sorted: the order pairs() visits them in never reaches a message.)
local function unknown_fields(args, known)
  local is_known, unknown = {}, {}
  for _, key in ipairs(known) do is_known[key] = true end
  for key in pairs(args) do
    if not is_known[key] then unknown[#unknown + 1] = type(key) == "string" and key or "[" .. shown(key) .. "]" end
  end
  if #unknown == 0 then return nil end
  table.sort(unknown)
  return table.concat(unknown, ", ")
end

-- Reads and checks a panel's options: the options, or nil and what is wrong.
-- fields: the options it takes, sorted; widths: the allowed widths; default_every(width).
local function read_panel(name, args, fields, widths, default_width, default_every)
  if type(args) ~= "table" then
    return nil, ("%s takes a table, e.g. %s{ rows = 12 }, not %s"):format(name, name, shown(args))
  end
  local unknown = unknown_fields(args, fields)
  if unknown then
    return nil, name .. ": unknown field(s) " .. unknown .. "; known fields: " .. table.concat(fields, ", ")
  end
  local o = {}
  o.rows = whole(args.rows, 1)
  if not o.rows then return nil, name .. ": rows must be a whole number from 1 up, not " .. shown(args.rows) end
  o.width = args.width == nil and default_width or whole(args.width, 1)
  if not (o.width and widths[o.width]) then
    return nil, name .. ": width must be " .. widths.text .. ", not " .. shown(args.width)
  end
  o.cross = args.cross == nil and "front" or args.cross  -- horseshoe: never given
  if o.cross ~= "front" and o.cross ~= "back" then
    return nil, name .. ": cross must be \"front\" or \"back\", not " .. shown(args.cross)
  end
  o.every = args.cross_every == nil and default_every(o.width) or whole(args.cross_every, 1)
  if not o.every then
    return nil, name .. ": cross_every must be a whole number from 1 up, not " .. shown(args.cross_every)
  end
  if knitting() == "flat" and o.every % 2 == 1 then
    return nil, ("%s: cross_every is %d, but flat cables cross on right-side rows only; make it even"):format(name, o.every)
  end
  o.border = args.purl_border == nil and 2 or whole(args.purl_border, 0)
  if not o.border then
    return nil, name .. ": purl_border must be a whole number from 0 up, not " .. shown(args.purl_border)
  end
  local n, repeat_width = live(), o.width + o.border
  if n > 0 and (n % repeat_width ~= o.border % repeat_width or n < repeat_width + o.border) then
    local plus = o.border > 0 and (" plus %d"):format(o.border) or ""
    return nil, ("%s needs a multiple of %d stitches%s (width %d, purl_border %d); %d are live"):format(
      name, repeat_width, plus, o.width, o.border, n)
  end
  return o
end

-- The panel row with `cable` (written stitches) between purl borders of `border`
-- stitches worked as `edge`.
local function panel_text(cable, border, edge)
  if border == 0 then return cable end
  local last = border == 1 and "1 st" or border .. " sts"
  return ("*%s%d, %s; rep from * to last %s, %s%d"):format(edge, border, cable, last, edge, border)
end

local function work_panel(o, crossing)
  for _ = 1, o.rows do
    if (chart_row() + 1) % o.every == 0 then
      row(panel_text(crossing, o.border, "p"))
    elseif not right_side() then
      row(panel_text("p" .. o.width, o.border, "k"))
    else
      row(panel_text("k" .. o.width, o.border, "p"))
    end
  end
end

local rope_widths = { [2] = true, [4] = true, [6] = true, [8] = true, text = "2, 4, 6 or 8" }

function cables.rope(args)
  local o, problem = read_panel("cables.rope", args, { "cross", "cross_every", "purl_border", "rows", "width" },
    rope_widths, 4, function(width) return width end)
  if not o then error(problem, 2) end
  work_panel(o, ("C%d%s"):format(o.width, o.cross == "front" and "F" or "B"))
end

local horseshoe_widths = { [4] = true, [8] = true, [12] = true, [16] = true, text = "4, 8, 12 or 16" }

function cables.horseshoe(args)
  local o, problem = read_panel("cables.horseshoe", args, { "cross_every", "purl_border", "rows", "width" },
    horseshoe_widths, 8, function(width) return width // 2 end)
  if not o then error(problem, 2) end
  local half = o.width // 2
  work_panel(o, ("C%dB, C%dF"):format(half, half))
end

return cables
