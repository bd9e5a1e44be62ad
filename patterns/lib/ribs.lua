-- ribs: ribbing and the small knit-and-purl textures, as functions that work rows.
--
--   local ribs = require "ribs"
--
-- The functions are declared below (working.define: their arguments are checked from the
-- declaration, and docs/language.md lists them). Each works `rows` rows and returns
-- nothing. The face comes out the same flat or in the round: the functions ask
-- right_side() and write a wrong-side row as a knitter does (k where the face shows p).
-- Garter, seed and moss follow the row numbers of the whole piece as a chart counts them
-- (odd rows of garter show knit, even rows the purl ridge; working.chart_row), so two
-- calls in a row continue one fabric. A bad argument is an error at the line that called
-- the function. No twisted rib: the stitch vocabulary has no "through the back loop" yet.

local ribs = {}

local row, live, right_side = row, live, right_side
local working = require "working"
local chart_row = working.chart_row

working.declare("ribs", "ribbing and the small knit-and-purl textures")

local rows_arg = { "rows", "whole", least = 1, doc = "rows worked" }

local function sts(n)
  return n == 1 and "1 st" or n .. " sts"
end

-- A kA, pB rib's written rows on n stitches: the right-side text and the wrong-side text
-- (which shows the same face), or nil when n does not fit the rib.
local function rib_texts(n, a, b)
  if n % (a + b) == 0 then
    return ("k%d, p%d"):format(a, b), ("k%d, p%d"):format(b, a)
  end
  if n % (a + b) == a and n >= 2 * a + b then
    return ("*k%d, p%d; rep from * to last %s, k%d"):format(a, b, sts(a), a),
        ("*p%d, k%d; rep from * to last %s, p%d"):format(a, b, sts(a), a)
  end
  return nil
end

-- Works a rib, or returns what is wrong before working anything.
local function work_rib(name, rows, a, b)
  local n = live()
  local rs, ws = rib_texts(n, a, b)
  if n > 0 and not rs then
    return ("%s needs a multiple of %d stitches, or of %d plus %d; %d are live"):format(name, a + b, a + b, a, n)
  end
  for _ = 1, rows do
    if right_side() then row(rs) else row(ws) end
  end
  return nil
end

ribs.rib = working.define("ribs", {
  name = "rib",
  doc = "a kN, pM rib. Stitches: a multiple of knits + purls, or that plus knits (the rib then starts and ends with "
    .. "knits: the usual way to rib a flat piece)",
  args = { rows_arg, { "knits", "whole", least = 1, doc = "N, the knit stitches of each rib" },
    { "purls", "whole", least = 1, doc = "M, the purl stitches between" } },
  work = function(rows, knits, purls)
    return work_rib(("ribs.rib(%d, %d)"):format(knits, purls), rows, knits, purls)
  end,
})

ribs.k1p1 = working.define("ribs", {
  name = "k1p1",
  doc = "k1, p1 rib: a multiple of 2, or of 2 plus 1",
  args = { rows_arg },
  work = function(rows) return work_rib("ribs.k1p1", rows, 1, 1) end,
})

ribs.k2p2 = working.define("ribs", {
  name = "k2p2",
  doc = "k2, p2 rib: a multiple of 4, or of 4 plus 2",
  args = { rows_arg },
  work = function(rows) return work_rib("ribs.k2p2", rows, 2, 2) end,
})

ribs.garter = working.define("ribs", {
  name = "garter",
  doc = "garter stitch: knit every row flat; in the round knit and purl rows alternate. Any stitch count",
  args = { rows_arg },
  work = function(rows)
    for _ = 1, rows do
      local face_knit = chart_row() % 2 == 1
      -- A row shows knit on the face when worked k from the right side or p from the wrong.
      row((face_knit == right_side()) and "k" or "p")
    end
  end,
})

-- One row of k1, p1 whose rightmost stitch on the face is a knit (right_knit) or a purl.
local function k1p1_row(n, right_knit)
  if n % 2 == 0 then
    -- On an even count the same text shows the same face from either side.
    row(right_knit and "k1, p1" or "p1, k1")
  elseif right_knit == right_side() then
    row("k1, *p1, k1; rep from *")
  else
    row("p1, *k1, p1; rep from *")
  end
end

-- Seed and moss: k1, p1 whose phase follows the row number.
local function work_k1p1_texture(name, rows, right_knit_on)
  local n = live()
  if n == 1 then return name .. " needs at least 2 stitches; 1 is live" end
  for _ = 1, rows do
    k1p1_row(n, right_knit_on(chart_row()))
  end
  return nil
end

ribs.seed = working.define("ribs", {
  name = "seed",
  doc = "seed stitch (US seed, UK moss): k1, p1, moved over one stitch every row. Any count of 2 or more",
  args = { rows_arg },
  work = function(rows)
    return work_k1p1_texture("ribs.seed", rows, function(r) return r % 2 == 1 end)
  end,
})

ribs.moss = working.define("ribs", {
  name = "moss",
  doc = "US moss stitch (UK double moss): k1, p1, moved over one stitch every 2 rows, a 4-row repeat. Any count of "
    .. "2 or more. For UK moss stitch call ribs.seed",
  args = { rows_arg },
  work = function(rows)
    return work_k1p1_texture("ribs.moss", rows, function(r) return (r - 1) % 4 < 2 end)
  end,
})

return ribs
