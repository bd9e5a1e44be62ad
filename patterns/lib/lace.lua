-- lace: eyelets and lace patterns that keep the stitch count: every yarn over is paired
-- with a decrease in the same row.
--
--   local lace = require "lace"
--
-- The functions are declared below (working.define: their arguments are checked from the
-- declaration, and docs/language.md lists them). Each works `rows` rows and returns
-- nothing. Chevron and feather and fan follow the row numbers of the whole piece as a
-- chart counts them (working.chart_row: its row 1 is a right-side row): their lace rows
-- are the chart's odd rows, the right side in flat knitting, and a second call continues
-- the first. Flat or in the round, the face comes out the same. A bad argument is an
-- error at the line that called the function.

local lace = {}

local row, live, right_side = row, live, right_side
local working = require "working"
local chart_row = working.chart_row

working.declare("lace", "eyelets and lace patterns that keep the stitch count")

local rows_arg = { "rows", "whole", least = 1, doc = "rows worked" }

-- One row whose face is all knit (stockinette) or all purl.
local function plain_row(face_knit)
  row((face_knit == right_side()) and "k" or "p")
end

-- What is wrong with the live count for a pattern repeating over `multiple`, or nil.
local function multiple_problem(name, multiple, least)
  local n = live()
  if n == 0 or (n % multiple == 0 and n >= least) then return nil end
  return ("%s needs a multiple of %d stitches%s; %d are live"):format(
    name, multiple, least > multiple and (", at least " .. least) or "", n)
end

lace.eyelet_row = working.define("lace", {
  name = "eyelet_row",
  doc = "one row of eyelets, k1, *yo, k2tog; rep from * to last st, k1, then rows - 1 rows of stockinette: a "
    .. "drawstring or ribbon row. An even count of 4 or more. On a wrong-side row it is worked p1, *yo, p2tog, ..., p1",
  args = { { "rows", "whole", least = 1, default = 1, doc = "rows worked, the eyelets' first" } },
  work = function(rows)
    local problem = multiple_problem("lace.eyelet_row", 2, 4)
    if problem then return problem end
    if right_side() then
      row "k1, *yo, k2tog; rep from * to last 1 st, k1"
    else
      row "p1, *yo, p2tog; rep from * to last 1 st, p1"
    end
    for _ = 2, rows do plain_row(true) end
  end,
})

lace.chevron = working.define("lace", {
  name = "chevron",
  doc = "chevron lace: *k1, yo, k2, cdd, k2, yo; rep from * on the chart's odd rows, stockinette on the even ones. A "
    .. "multiple of 8",
  args = { rows_arg },
  work = function(rows)
    local problem = multiple_problem("lace.chevron", 8, 8)
    if problem then return problem end
    for _ = 1, rows do
      if chart_row() % 2 == 1 then
        row "*k1, yo, k2, cdd, k2, yo; rep from *"
      else
        plain_row(true)
      end
    end
  end,
})

lace.feather_and_fan = working.define("lace", {
  name = "feather_and_fan",
  doc = "feather and fan (Old Shale), a 4-row repeat: row 1 knit, row 2 purl (the face knit), row 3 *(k2tog) x3, "
    .. "(yo, k1) x6, (k2tog) x3; rep from *, row 4 knit (the face purl, a ridge). A multiple of 18; rows a multiple "
    .. "of 4 ends a repeat",
  args = { rows_arg },
  work = function(rows)
    local problem = multiple_problem("lace.feather_and_fan", 18, 18)
    if problem then return problem end
    for _ = 1, rows do
      local step = (chart_row() - 1) % 4 + 1
      if step == 3 then
        row "*(k2tog) x3, (yo, k1) x6, (k2tog) x3; rep from *"
      else
        plain_row(step ~= 4)
      end
    end
  end,
})

return lace
