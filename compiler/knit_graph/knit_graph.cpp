#include "knit_graph/knit_graph.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace knitc::knit_graph {

namespace {

// A drop: the live loop is let off and its wale unravels, each loop down the wale losing
// the one pulled through it, to the yarn over (or cast-on or make-one) it grew from,
// which comes undone too. Every loop of the run becomes a rung. A wale unravels as one
// only through loops of one parent and one child: a decrease, an increase, or a tuck
// held with it stops it, and the row is refused rather than drawn half undone.
void unravel(Graph& g, std::vector<int>& children, const std::vector<int>& live, int course) {
  auto row = [](int c) { return c == 0 ? std::string("the cast-on") : "row " + std::to_string(c); };
  if (live.size() != 1)
    throw RowError(course, row(course) + " drops a stitch holding a tuck (" + std::to_string(live.size()) +
                               " loops on one needle); knit the tuck off before dropping the stitch");
  for (int l = live.front();;) {
    Loop& loop = g.loops[static_cast<std::size_t>(l)];
    if (loop.parents.size() > 1)
      throw RowError(course, row(course) + " drops a stitch whose wale would unravel down through " +
                                 std::to_string(loop.parents.size()) + " stitches worked together at " + row(loop.course) +
                                 "; a dropped stitch unravels to a yarn over: drop one made by a yo above that row");
    if (!loop.parents.empty() && children[static_cast<std::size_t>(loop.parents.front())] > 1)
      throw RowError(course, row(course) + " drops a stitch whose wale would unravel into an increase worked at " +
                                 row(loop.course) +
                                 " (one stitch worked several times); drop a stitch made by a yo above that row");
    loop.unravelled = true;
    if (loop.parents.empty()) return;
    const int parent = loop.parents.front();
    loop.parents.clear();
    children[static_cast<std::size_t>(parent)] = 0;
    l = parent;
  }
}

// A stitch worked under the floats: it catches every loose float over its stitch on the
// side it is pulled out to (in front for a knit), and the others stay loose. Returns them.
std::vector<int> catch_floats(Graph& g, std::vector<int> loose, int loop, bool in_front, int course) {
  std::vector<int> left;
  int caught = 0;
  for (int f : loose) {
    Float& fl = g.floats[static_cast<std::size_t>(f)];
    if (fl.in_front != in_front) {
      left.push_back(f);
      continue;
    }
    fl.caught_by = loop;
    ++caught;
  }
  if (caught == 0)
    throw RowError(course, "row " + std::to_string(course) + " works a stitch under the loose strand, but no float lies over it on the " +
                               (in_front ? "face" : "back") + " within " + std::to_string(float_reach - 1) +
                               " rows below; slip the stitches under it with the yarn on that side on an earlier row (sl wyif on a "
                               "right-side row for the face)");
  return left;
}

// Worked into the stitch below (brioche's k1 below): the needle goes through the loops
// the live ones were pulled through, and the live loops drop off onto the new loop,
// held by it as a tuck is. So the live loops lose their parents to the new loop and
// become held loops beside them; a cast-on loop has none to give and is simply worked.
std::vector<int> drop_into_stitch_below(Graph& g, std::vector<int>& children, std::vector<int> live) {
  std::vector<int> parents;
  for (int l : live) {
    Loop& dropped = g.loops[static_cast<std::size_t>(l)];
    if (dropped.parents.empty() || dropped.held) {
      parents.push_back(l);
      continue;
    }
    parents.insert(parents.end(), dropped.parents.begin(), dropped.parents.end());
    for (int p : dropped.parents) --children[static_cast<std::size_t>(p)];  // the new loop counts them again
    dropped.parents.clear();
    dropped.held = true;
    parents.push_back(l);
  }
  return parents;
}

}  // namespace

Graph build(const Pattern& pattern) {
  Graph g;
  std::vector<std::vector<int>> live;
  std::vector<int> children;  // per loop: the loops pulled through it
  g.course_first.push_back(0);
  const StitchId knit = stitch_id("k");
  for (int i = 0; i < pattern.cast_on; ++i) {
    Loop l;
    l.course = 0;
    l.position = i;
    l.slot = i;
    l.stitch = knit;
    l.yarn = pattern.cast_on_yarn;
    g.loops.push_back(l);
    children.push_back(0);
    live.push_back({i});
  }
  // Per live stitch: the floats lying over it not yet caught, from the last float_reach rows.
  std::vector<std::vector<int>> loose(live.size());
  g.needle.push_back(pattern.cast_on);
  g.columns.push_back(pattern.cast_on);
  g.stands_on.emplace_back();
  std::vector<int> live_columns(live.size());  // each live stitch's column in the course below
  std::iota(live_columns.begin(), live_columns.end(), 0);
  std::vector<int> yarn_order(pattern.yarns.size(), 0);
  for (int y = 0; y < static_cast<int>(pattern.yarns.size()); ++y) {
    if (y == pattern.cast_on_yarn) yarn_order[y] = pattern.cast_on;
  }
  // The cast-on ends where the first row starts: flat work turns at the edge, so a cast-on
  // under a right-side row (worked from the right edge) runs left to right; in the round
  // every course, the cast-on too, runs right to left.
  const bool cast_on_leftwards = pattern.knitting == Knitting::round ||
                                 (!pattern.courses.empty() && pattern.courses.front().side == Side::wrong);
  for (int i = 0; i < pattern.cast_on; ++i) g.loops[i].order = cast_on_leftwards ? pattern.cast_on - 1 - i : i;

  for (std::size_t c = 0; c < pattern.courses.size(); ++c) {
    const Course& course = pattern.courses[c];
    const int number = static_cast<int>(c) + 1;
    g.course_first.push_back(static_cast<int>(g.loops.size()));
    const int needed = consumed(course);
    if (needed != static_cast<int>(live.size()))
      throw RowError(number, "row " + std::to_string(number) + " works " + std::to_string(needed) + " stitches but " +
                                  std::to_string(live.size()) + " are live");
    std::vector<std::vector<int>> next, next_loose;
    // The loose floats of live stitches [from, from + n), those float_reach rows down let go.
    auto loose_over = [&](std::size_t from, int n) {
      std::vector<int> out;
      for (int k = 0; k < n; ++k)
        for (int f : loose[from + static_cast<std::size_t>(k)]) {
          const Float& fl = g.floats[static_cast<std::size_t>(f)];
          if (fl.caught_by < 0 && fl.course > number - float_reach && std::find(out.begin(), out.end(), f) == out.end())
            out.push_back(f);
        }
      std::sort(out.begin(), out.end());
      return out;
    };
    const std::size_t first_loop = g.loops.size();
    std::size_t at = 0;  // next live stitch, face order
    int position = 0;
    int bound = 0;  // stitches bound off so far in the course: columns without a needle
    std::vector<Column>& stands_on = g.stands_on.emplace_back();
    std::vector<int> next_columns;
    for (const Op& op : course.ops) {
      const StitchDef& s = stitch(op.stitch);
      const std::size_t op_at = at, next_before = next.size();
      const int bound_before = bound;
      auto new_loop = [&](std::vector<int> parents, bool held) {
        Loop l;
        l.course = number;
        l.position = position++;
        l.slot = static_cast<int>(next.size()) + bound;
        l.stitch = op.stitch;
        l.yarn = op.yarn;
        l.parents = std::move(parents);
        l.held = held;
        for (int p : l.parents) ++children[static_cast<std::size_t>(p)];
        g.loops.push_back(std::move(l));
        children.push_back(0);
        return static_cast<int>(g.loops.size()) - 1;
      };
      // A plated stitch's second loop, beside `first` (just made): the stitch is then both.
      auto plate = [&](int first) {
        std::vector<int> stitch_loops{first};
        if (op.plated < 0) return stitch_loops;
        const int second = new_loop(g.loops[static_cast<std::size_t>(first)].parents, g.loops[static_cast<std::size_t>(first)].held);
        g.loops[static_cast<std::size_t>(second)].yarn = op.plated;
        g.loops[static_cast<std::size_t>(second)].plating = true;
        stitch_loops.push_back(second);
        return stitch_loops;
      };
      if (s.wraps > 0) {  // each stitch knitted, then the yarn wound round them all
        const int first = static_cast<int>(g.loops.size());
        for (int k = 0; k < s.consumes; ++k) {
          next.push_back({new_loop(live[at + static_cast<std::size_t>(k)], false)});
          next_loose.push_back(loose_over(at + static_cast<std::size_t>(k), 1));
        }
        g.wraps.push_back({number, first, static_cast<int>(g.loops.size()) - 1, op.yarn, s.wraps});
      } else if (s.bobble_loops > 0) {  // a row of loops out of one stitch, rows on them, gathered
        Bobble b{number, static_cast<int>(g.loops.size()), s.bobble_loops, s.bobble_rows};
        for (int r = 0; r < b.rows; ++r)
          for (int k = 0; k < b.loops; ++k)
            new_loop(r == 0 ? live[at] : std::vector<int>{b.first + (r - 1) * b.loops + k}, false);
        std::vector<int> last(static_cast<std::size_t>(b.loops));
        for (int k = 0; k < b.loops; ++k) last[static_cast<std::size_t>(k)] = b.first + (b.rows - 1) * b.loops + k;
        next.push_back({new_loop(std::move(last), false)});
        next_loose.push_back(loose_over(at, 1));
        g.bobbles.push_back(b);
      } else {
        switch (s.family) {
          case StitchFamily::slip: {
            if (s.unreached) {  // held: left as it was, no yarn across it
              next.push_back(live[at]);
              next_loose.push_back(loose_over(at, 1));
              break;
            }
            // Stitches slipped one after another ("sl3 wyif") leave one float across them all.
            const bool in_front = op.stitch == stitch_id("sl wyif");
            const int first = static_cast<int>(next.size()) + bound;
            if (!g.floats.empty() && g.floats.back().course == number && g.floats.back().yarn == op.yarn &&
                g.floats.back().in_front == in_front && g.floats.back().last + 1 == first)
              g.floats.back().last = first + s.consumes - 1;
            else
              g.floats.push_back({number, first, first + s.consumes - 1, op.yarn, in_front});
            for (int k = 0; k < s.consumes; ++k) {
              next.push_back(live[at + k]);
              next_loose.push_back(loose_over(at + k, 1));
              next_loose.back().push_back(static_cast<int>(g.floats.size()) - 1);
            }
            break;
          }
          case StitchFamily::tuck:
            for (int k = 0; k < s.consumes; ++k) {
              std::vector<int> held = live[at + k];
              for (int t : plate(new_loop({}, true))) held.push_back(t);
              next.push_back(std::move(held));
              next_loose.push_back(loose_over(at + k, 1));
            }
            break;
          case StitchFamily::no_stitch: break;
          case StitchFamily::drop: unravel(g, children, live[at], number); break;
          case StitchFamily::bind_off:
            g.loops[static_cast<std::size_t>(new_loop(live[at], false))].bound = true;
            ++bound;
            break;
          case StitchFamily::cable:
            for (int j = 0; j < s.produces; ++j) {
              next.push_back(plate(new_loop(live[at + cable_source(s, j)], false)));
              next_loose.push_back(loose_over(at + static_cast<std::size_t>(cable_source(s, j)), 1));
            }
            break;
          default: {  // knit, purl, yarn over, decreases: one new loop through all they take
            std::vector<int> parents;
            for (int k = 0; k < s.consumes; ++k) parents.insert(parents.end(), live[at + k].begin(), live[at + k].end());
            if (s.below) parents = drop_into_stitch_below(g, children, std::move(parents));
            std::vector<int> over = loose_over(at, s.consumes);
            for (int k = 0; k < s.produces; ++k) {
              // An increase works every new loop through the old one; a yarn over has none.
              const int made = new_loop(k == 0 || s.family == StitchFamily::increase ? parents : std::vector<int>{}, false);
              next.push_back(plate(made));
              if (s.catches) over = catch_floats(g, std::move(over), made, !purled(s), number);
              next_loose.push_back(over);
            }
            break;
          }
        }
      }
      at += static_cast<std::size_t>(s.consumes);
      // The columns this op made, in order (a bound-off stitch's, or live ones), each on
      // the stitch it took (a cable's loop on the one it crosses from, a decrease on all
      // it gathered); a yarn over on none.
      const std::size_t columns_made = next.size() - next_before + static_cast<std::size_t>(bound - bound_before);
      const bool gathers = columns_made == 1 && s.consumes > 1;
      for (std::size_t k = 0; k < columns_made; ++k) {
        Column column;
        if (s.consumes > 0) {
          const int j = static_cast<int>(k);
          const std::size_t from = op_at + static_cast<std::size_t>(s.family == StitchFamily::cable ? cable_source(s, j)
                                                                                                   : std::min(j, s.consumes - 1));
          column.below = live_columns[from];
          column.across = gathers ? live_columns[op_at + static_cast<std::size_t>(s.consumes) - 1] - column.below + 1 : 1;
        }
        column.reached = !s.unreached;
        column.pulled = s.family != StitchFamily::slip && s.family != StitchFamily::tuck;
        if (bound == bound_before) next_columns.push_back(static_cast<int>(stands_on.size()));
        stands_on.push_back(column);
      }
    }
    // Order along the yarn: right-side rows are worked from the right edge.
    const std::size_t made = g.loops.size() - first_loop;
    for (std::size_t k = 0; k < made; ++k) {
      Loop& l = g.loops[course.side == Side::right ? first_loop + made - 1 - k : first_loop + k];
      l.order = yarn_order[l.yarn]++;
    }
    // A bobble's rows turn: its loops take the same places along the yarn, reordered as
    // worked: row 0 as its course goes, each next row back the other way, then the gather.
    for (auto b = g.bobbles.rbegin(); b != g.bobbles.rend() && b->course == number; ++b) {
      const int n = b->loops;
      std::vector<int> orders;
      for (int i = b->first; i <= b->gathered(); ++i) orders.push_back(g.loops[static_cast<std::size_t>(i)].order);
      std::sort(orders.begin(), orders.end());
      std::size_t next_order = 0;
      for (int r = 0; r < b->rows; ++r) {
        const bool leftwards = (course.side == Side::right) == (r % 2 == 0);
        for (int k = 0; k < n; ++k)
          g.loops[static_cast<std::size_t>(b->first + r * n + (leftwards ? n - 1 - k : k))].order = orders[next_order++];
      }
      g.loops[static_cast<std::size_t>(b->gathered())].order = orders[next_order];
    }
    g.needle.push_back(static_cast<int>(next.size()));
    g.columns.push_back(static_cast<int>(next.size()) + bound);
    live = std::move(next);
    loose = std::move(next_loose);
    live_columns = std::move(next_columns);
  }
  g.course_first.push_back(static_cast<int>(g.loops.size()));
  g.live = std::move(live);
  g.live_columns = std::move(live_columns);
  return g;
}

}  // namespace knitc::knit_graph
