-- cables: cable panels as functions that work rows.
--
--   local cables = require "cables"
--
-- The functions are declared below (working.define: the fields of the table each takes
-- are checked from the declaration, and docs/language.md lists them).
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
local chart_row = working.chart_row

working.declare("cables", "cable panels")

local rows_field = { "rows", "whole", least = 1, doc = "rows worked" }
local function every_field(default_doc)
  return { "cross_every", "whole", least = 1, optional = true, default_doc = default_doc,
    doc = "rows from one crossing to the next" }
end
local border_field = { "purl_border", "whole", least = 0, default = 2,
  doc = "purl stitches between and beside the cables (may be 0)" }

-- The panel's options checked together, or nil and what is wrong before working anything.
local function panel(name, rows, width, every, border)
  if knitting() == "flat" and every % 2 == 1 then
    return nil, ("%s: cross_every is %d, but flat cables cross on right-side rows only; make it even"):format(name, every)
  end
  local n, repeat_width = live(), width + border
  if n > 0 and (n % repeat_width ~= border % repeat_width or n < repeat_width + border) then
    local plus = border > 0 and (" plus %d"):format(border) or ""
    return nil, ("%s needs a multiple of %d stitches%s (width %d, purl_border %d); %d are live"):format(
      name, repeat_width, plus, width, border, n)
  end
  return { rows = rows, width = width, every = every, border = border }
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

cables.rope = working.define("cables", {
  name = "rope",
  doc = "a rope cable: width knit stitches crossed half over half with C<width>F (cross = \"front\", the front half "
    .. "moves left) or C<width>B (\"back\", it moves right) every cross_every rows, between purl borders. Stitches: a "
    .. "multiple of width + purl_border, plus purl_border; e.g. 14 for two 4-stitch ropes with 2 purls around each",
  fields = { rows_field,
    { "width", "whole", values = { 2, 4, 6, 8 }, default = 4, doc = "the cable's knit stitches" },
    { "cross", "choice", choices = { "front", "back" }, default = "front", doc = "where the cable needle is held" },
    every_field("the width"), border_field },
  work = function(rows, width, cross, every, border)
    local o, problem = panel("cables.rope", rows, width, every or width, border)
    if not o then return problem end
    work_panel(o, ("C%d%s"):format(width, cross == "front" and "F" or "B"))
  end,
})

cables.horseshoe = working.define("cables", {
  name = "horseshoe",
  doc = "a horseshoe cable: width knit stitches; the crossing row works the right half C<half>B and the left half "
    .. "C<half>F, so the stitches part from the centre. Stitches as for rope",
  fields = { rows_field,
    { "width", "whole", values = { 4, 8, 12, 16 }, default = 8, doc = "the cable's knit stitches" },
    every_field("half the width"), border_field },
  work = function(rows, width, every, border)
    local o, problem = panel("cables.horseshoe", rows, width, every or width // 2, border)
    if not o then return problem end
    local half = width // 2
    work_panel(o, ("C%dB, C%dF"):format(half, half))
  end,
})

return cables
