#include "knit_graph/knit_graph.hpp"

#include <stdexcept>
#include <string>

namespace knitc::knit_graph {

namespace {

// The new loops a cable makes take their parents from the block crossed: new position j
// of a block of n with h held stitches comes from old position (j < h ? n - h + j : j - h);
// in a three-part cross the outer h on each side change places around the middle.
int cable_source(const StitchDef& s, int j) {
  const int n = s.consumes, h = s.cable.held;
  if (s.cable.middle > 0) return j < h ? n - h + j : j >= n - h ? j - (n - h) : j;
  return j < h ? n - h + j : j - h;
}

// Worked into the stitch below (brioche's k1 below): the needle goes through the loops
// the live ones were pulled through, and the live loops drop off onto the new loop,
// held by it as a tuck is. So the live loops lose their parents to the new loop and
// become held loops beside them; a cast-on loop has none to give and is simply worked.
std::vector<int> drop_into_stitch_below(Graph& g, std::vector<int> live) {
  std::vector<int> parents;
  for (int l : live) {
    Loop& dropped = g.loops[static_cast<std::size_t>(l)];
    if (dropped.parents.empty() || dropped.held) {
      parents.push_back(l);
      continue;
    }
    parents.insert(parents.end(), dropped.parents.begin(), dropped.parents.end());
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
    live.push_back({i});
  }
  g.needle.push_back(pattern.cast_on);
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
      throw std::invalid_argument("row " + std::to_string(number) + " works " + std::to_string(needed) + " stitches but " +
                                  std::to_string(live.size()) + " are live");
    std::vector<std::vector<int>> next;
    const std::size_t first_loop = g.loops.size();
    std::size_t at = 0;  // next live stitch, face order
    int position = 0;
    for (const Op& op : course.ops) {
      const StitchDef& s = stitch(op.stitch);
      auto new_loop = [&](std::vector<int> parents, bool held) {
        Loop l;
        l.course = number;
        l.position = position++;
        l.slot = static_cast<int>(next.size());
        l.stitch = op.stitch;
        l.yarn = op.yarn;
        l.parents = std::move(parents);
        l.held = held;
        g.loops.push_back(std::move(l));
        return static_cast<int>(g.loops.size()) - 1;
      };
      switch (s.family) {
        case StitchFamily::slip:
          g.floats.push_back({number, static_cast<int>(next.size()), static_cast<int>(next.size()) + s.consumes - 1,
                              op.yarn, op.stitch == stitch_id("sl wyif")});
          for (int k = 0; k < s.consumes; ++k) next.push_back(live[at + k]);
          break;
        case StitchFamily::tuck:
          for (int k = 0; k < s.consumes; ++k) {
            std::vector<int> held = live[at + k];
            held.push_back(new_loop({}, true));
            next.push_back(std::move(held));
          }
          break;
        case StitchFamily::no_stitch: break;
        case StitchFamily::cable:
          for (int j = 0; j < s.produces; ++j) {
            const int made = new_loop(live[at + cable_source(s, j)], false);
            next.push_back({made});
          }
          break;
        default: {  // knit, purl, yarn over, decreases: one new loop through all they take
          std::vector<int> parents;
          for (int k = 0; k < s.consumes; ++k) parents.insert(parents.end(), live[at + k].begin(), live[at + k].end());
          if (s.below) parents = drop_into_stitch_below(g, std::move(parents));
          for (int k = 0; k < s.produces; ++k) {
            // An increase works every new loop through the old one; a yarn over has none.
            const int made = new_loop(k == 0 || s.family == StitchFamily::increase ? parents : std::vector<int>{}, false);
            next.push_back({made});
          }
          break;
        }
      }
      at += static_cast<std::size_t>(s.consumes);
    }
    // Order along the yarn: right-side rows are worked from the right edge.
    const std::size_t made = g.loops.size() - first_loop;
    for (std::size_t k = 0; k < made; ++k) {
      Loop& l = g.loops[course.side == Side::right ? first_loop + made - 1 - k : first_loop + k];
      l.order = yarn_order[l.yarn]++;
    }
    g.needle.push_back(static_cast<int>(next.size()));
    live = std::move(next);
  }
  g.course_first.push_back(static_cast<int>(g.loops.size()));
  g.live = std::move(live);
  return g;
}

}  // namespace knitc::knit_graph
