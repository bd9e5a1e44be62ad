// The course layout: every loop of the knit graph placed as the seed paper's 17-point
// loop (Table 1) in its course and needle position, then moved by its stitch (pulled
// through its parents, leaning across for cables, gathered, held, stood out in a bobble).
// The passes of lay_out, in order, each working on the layout made so far (the courses'
// needle positions are courses.cpp's, the templates' shapes in layout.hpp, the loops'
// graph in knit_graph).
#include "layout/layout.hpp"

#include "layout/courses.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include <glm/vec2.hpp>

namespace knitc::layout {

namespace {
// Table 1 of Li, Yang, Chen, Xu (2014), as printed.
constexpr std::array<glm::dvec3, loop_points> table1 = {{
    {0.0000, 0.0000, 0.0000}, {0.2500, 0.0407, 0.1275}, {0.3493, 0.2035, 0.5966},
    {0.3145, 0.3494, 0.8901}, {0.2398, 0.4954, 0.9999}, {0.1751, 0.6486, 0.8930},
    {0.1488, 0.7874, 0.6193}, {0.2190, 0.9230, 0.2396}, {0.5000, 1.0000, 0.0000},
    {0.7810, 0.9230, 0.2396}, {0.8512, 0.7874, 0.6193}, {0.8249, 0.6486, 0.8930},
    {0.7602, 0.4954, 0.9999}, {0.6855, 0.3494, 0.8901}, {0.6507, 0.2035, 0.5966},
    {0.7500, 0.0407, 0.1275}, {1.0000, 0.0000, 0.0000},
}};

// How much of a shift a loop's points take: a parent's head weights are 1 over the needle
// loop (P6..P10) and 0 at the sinker loops; a child's leg weights the other way round,
// also 0 at P0 and P16 so that loops of a course keep sharing their end points.
constexpr std::array<double, loop_points> head = {0.0, 0.0, 0.1, 0.3, 0.55, 0.8, 1.0, 1.0, 1.0,
                                                  1.0, 1.0, 0.8, 0.55, 0.3, 0.1, 0.0, 0.0};
constexpr std::array<double, loop_points> legs = {0.0, 0.6, 0.9, 0.8, 0.6, 0.4, 0.2, 0.05, 0.0,
                                                  0.05, 0.2, 0.4, 0.6, 0.8, 0.9, 0.6, 0.0};
// A crossing loop's feet stay in its parent's head, its own head (P7..P9, as a whole)
// moves to its new needle position: the whole loop leans, the sinker loops at its feet
// included (but see crossed_sinker_gap).
constexpr std::array<double, loop_points> feet = {1.0, 1.0, 1.0, 0.9, 0.75, 0.55, 0.35, 0.1, 0.0,
                                                  0.1, 0.35, 0.55, 0.75, 0.9, 1.0, 1.0, 1.0};
// Where crossing legs pass in front of or behind each other: most at mid-leg.
constexpr std::array<double, loop_points> crossing = {0.3, 0.5, 0.8, 1.0, 1.0, 0.8, 0.5, 0.2, 0.0,
                                                      0.2, 0.5, 0.8, 1.0, 1.0, 0.8, 0.5, 0.3};

// A twisted stitch (through the back loop): the lower legs change sides, the one from
// the left foot passing in front, so the loop is crossed on itself at its base.
constexpr std::array<double, loop_points> twist_swap = {0.0, 0.6, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0,
                                                        0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 0.6, 0.0};
constexpr std::array<double, loop_points> twist_depth = {0.0, 1.0, 1.0, 1.0, 0.6, 0.2, 0.0, 0.0, 0.0,
                                                         0.0, 0.0, 0.0, -0.2, -0.6, -1.0, -1.0, 0.0};

// Where a crossing loop's neighbour leans otherwise, their sinker points part: each stops
// this far (of W) short of its full lean, so that two crossed loops' outer sinker points
// do not meet on one spot (still inside P1, 0.25 W in).
constexpr double crossed_sinker_gap = 0.15;

// A yarn over in lace has no parent to wrap its legs round: the strand lies over the
// needle, and the hole under it is the eyelet. Its loop is drawn with its legs this much
// of their length (the head where a plain loop's is, the feet on the course's line) and
// half as deep.
constexpr double eyelet_legs = 0.35;

// A decrease's heads under the top one lie this far (of d) lower at the head: enough that
// the heads are not on one line seen from the face (tests/lace_test.cpp); at 0.2 more
// yarns passed through in eyelet_lace (8, none at 0.05).
constexpr double gathered_drop = 0.05;

// A ladder's rung rises this far (of C) at its middle.
constexpr double rung_bow = 0.25;

// Of a gathered stitch's parents, the one lying on top: k2tog's left stitch (it leans
// right), ssk's and sk2p's right one (they lean left), the centre of a cdd.
std::size_t top_parent(const StitchDef& s, std::size_t parents) {
  switch (s.lean) {
    case Lean::left: return parents - 1;
    case Lean::centre: return parents / 2;
    default: return 0;
  }
}

}  // namespace

std::span<const glm::dvec3, loop_points> plain_loop_fractions() { return table1; }

std::array<glm::dvec3, loop_points> plain_loop(const Gauge& g) {
  std::array<glm::dvec3, loop_points> p;
  const glm::dvec3 scale(g.loop_width, g.loop_height, g.thickness);
  for (int i = 0; i < loop_points; ++i) p[i] = table1[i] * scale;
  return p;
}

Layout lay_out(const Pattern& pattern) { return lay_out(pattern, knit_graph::build(pattern)); }

namespace {

// The passes of lay_out, in order. Each works on the layout made so far.

// The graph's loops, each with the template it is drawn by.
void take_loops(Layout& out, const knit_graph::Graph& graph) {
  const double W = out.loop_width;
  for (std::size_t i = 0; i < graph.loops.size(); ++i) {
    const knit_graph::Loop& k = graph.loops[i];
    Loop& l = out.loops[i];
    l.course = k.course;
    l.wale = k.slot;
    l.stitch = k.stitch;
    l.yarn = k.yarn;
    l.order = k.order;
    l.plating = k.plating;
    const StitchDef& s = stitch(k.stitch);
    if (k.unravelled) l.shape = Template::rung;
    else if (k.bound) l.shape = Template::bind_off;
    else if (k.held) l.shape = Template::tuck;
    else if (purled(s)) l.shape = Template::purl;
    else if (s.family == StitchFamily::cable && s.cable.purl_background) {
      // A twist's travelling stitches (those crossing in front) are knit, the rest purled.
      // In a three-part cross only the middle, which stays put, is purled.
      const double from = centre_x(out, graph.loops[k.parents.front()].course, graph.loops[k.parents.front()].slot);
      const double to = centre_x(out, k.course, k.slot);
      const bool in_front = s.cable.front ? from > to : from < to;
      l.shape = (s.cable.middle > 0 ? std::abs(from - to) > 0.25 * W : in_front) ? Template::knit : Template::purl;
    }
  }
  for (const auto& b : out.bobbles)
    for (int r = 1; r < b.rows; r += 2)
      for (int k = 0; k < b.loops; ++k) out.loops[static_cast<std::size_t>(b.first + r * b.loops + k)].against = true;
}

}  // namespace

std::vector<char> in_bobbles(const Layout& out) {
  std::vector<char> in(out.loops.size(), 0);
  for (const auto& b : out.bobbles)
    for (int i = b.first; i <= b.gathered(); ++i) in[static_cast<std::size_t>(i)] = 1;
  return in;
}

namespace {

// The bind-off course after the graph's loops, worked with the yarn that worked last;
// its loops' parents are the live stitches.
void add_bind_off(Layout& out, const Pattern& pattern, const knit_graph::Graph& graph, std::vector<std::vector<int>>& parents) {
  const std::size_t graph_loops = graph.loops.size();
  const int course = out.courses - 1;
  int yarn = pattern.cast_on_yarn;
  if (!pattern.courses.empty()) {
    const Course& last = pattern.courses.back();
    if (!last.ops.empty()) yarn = (last.side == Side::right ? last.ops.front() : last.ops.back()).yarn;
  }
  int next_order = 0;
  for (const knit_graph::Loop& k : graph.loops) {
    if (k.yarn == yarn) next_order = std::max(next_order, k.order + 1);
  }
  const int n = static_cast<int>(graph.live.size());
  for (int s = 0; s < n; ++s) {
    Loop& l = out.loops[graph_loops + s];
    l.course = course;
    l.wale = s;
    l.stitch = stitch_id("k");
    l.yarn = yarn;
    l.order = next_order + (out.direction[course] < 0 ? n - 1 - s : s);
    l.shape = Template::bind_off;
    parents[graph_loops + s] = graph.live[s];
  }
}

// How a tuck loop lies against the loop it is held with (both knitted off by one later
// loop), per loop: 0 for every loop but a tuck.
enum TuckLie : char {
  purled_off = 1,  // knitted off as a purl: the tuck lies on the face's side
  level = 2,       // its feet as high as the loop it is held with: its column did not rise
                   // for its course (an intarsia carrier's tuck on the next part's edge)
};
std::vector<char> tuck_lies(const Layout& out, const knit_graph::Graph& graph, const std::vector<std::vector<int>>& parents) {
  std::vector<char> lie(out.loops.size(), 0);
  for (std::size_t i = 0; i < out.loops.size(); ++i)
    if (out.loops[i].shape == Template::purl)
      for (int p : parents[i])
        if (out.loops[static_cast<std::size_t>(p)].shape == Template::tuck) lie[static_cast<std::size_t>(p)] |= purled_off;
  if (out.column_y.empty()) return lie;  // courses laid whole: a tuck stands a course above
  for (std::size_t i = 0; i < out.loops.size(); ++i) {
    const Loop& tuck = out.loops[i];
    if (tuck.shape != Template::tuck || tuck.course == 0 || static_cast<std::size_t>(tuck.course) >= graph.stands_on.size()) continue;
    const auto& columns = graph.stands_on[static_cast<std::size_t>(tuck.course)];
    if (static_cast<std::size_t>(tuck.wale) >= columns.size()) continue;
    const knit_graph::Column& k = columns[static_cast<std::size_t>(tuck.wale)];
    if (k.below < 0) continue;
    double below = -std::numeric_limits<double>::infinity();
    for (int s = k.below; s < k.below + k.across; ++s) below = std::max(below, foot_y(out, tuck.course - 1, s));
    if (std::abs(foot_y(out, tuck.course, tuck.wale) - below) < 1e-9 * out.course_spacing) lie[i] |= level;
  }
  return lie;
}

// How far behind the loop it is held with a level tuck lies (TuckLie::level), in its
// yarn's diameters: at the feet, where the template puts both on one point, their cores
// clear and their shells pressed, as two loops in one needle's hook. Relaxed, CMU's
// intarsia passed 58 of its 13,000 crossings through with none (the template's 0.4 d
// behind the legs, 0 at the feet); 36 at 0.5, 2 at 0.7, 1 at 0.8, 0 from 0.9 to 1.2, 1 at
// 1.5. The tentacle's lone tucks of a carrier that goes on along the other bed, 5 with
// none, passed 4 to 25 over the same range, with no trend (5, 5, 4, 12, 25, 9, 7).
constexpr double level_tuck_behind = 0.8;

// How far a plating yarn's loop lies above its stitch's first yarn's, in the plating
// yarn's diameters. Relaxed, a plated jersey, a plated 1x1 rib and plated stripes (20 to
// 30 needles) passed no yarn through another from 0.5 to 0.7; at 0, 58 of 7,276 crossings
// of the jersey; at 0.3, 8; at 1.0, 28.
constexpr double plating_rise = 0.6;

// Every loop at its needle position by its stitch's template.
void place_templates(Layout& out, const Pattern& pattern, const std::vector<char>& tucks) {
  const auto plain = plain_loop(pattern.gauge);
  const double W = out.loop_width, C = out.course_spacing, H = pattern.gauge.loop_height;
  const StitchId yo = stitch_id("yo");
  // Lace: a course that decreases beside its yarn overs (their eyelets keep the count).
  // A yarn over between two decreases (a mesh, every other stitch a yarn over) keeps the
  // plain loop's legs: the decreases' leaning legs take its column's edges, and drawn
  // short there more yarns passed through (CMU's image lace tests: 55 and 81 of 14,000
  // crossings with the plain legs; 423 and 267 short).
  std::vector<std::vector<char>> decrease_at(static_cast<std::size_t>(out.courses));  // empty: the course has none
  for (const Loop& l : out.loops) {
    if (stitch(l.stitch).family != StitchFamily::decrease) continue;
    auto& at = decrease_at[static_cast<std::size_t>(l.course)];
    if (at.size() <= static_cast<std::size_t>(l.wale)) at.resize(static_cast<std::size_t>(l.wale) + 1, 0);
    at[static_cast<std::size_t>(l.wale)] = 1;
  }
  auto decreases = [&](int course, int wale) {
    const auto& at = decrease_at[static_cast<std::size_t>(course)];
    return wale >= 0 && static_cast<std::size_t>(wale) < at.size() && at[static_cast<std::size_t>(wale)];
  };
  for (std::size_t index = 0; index < out.loops.size(); ++index) {
    Loop& l = out.loops[index];
    const Span span = span_of(out, l.course, l.wale);
    const double d = pattern.yarns[l.yarn].diameter;
    double depth = layered(out, l.course) ? out.layers[l.course][l.wale] * out.layer_depth : 0.0;
    // A plating yarn lies against the loop before it (its stitch's first yarn), on that
    // loop's technical face: in front of a knit, behind a purl.
    if (l.plating) depth += (l.shape == Template::purl ? -0.5 : 0.5) * (d + pattern.yarns[out.loops[index - 1].yarn].diameter);
    // and a little above it: its loop a copy of the first's moved straight forward would
    // lie on the first's line seen from the face, where which crosses which is undecided.
    const double up = l.plating ? plating_rise * d : 0.0;
    const glm::dvec3 origin(span.left, foot_y(out, l.course, l.wale) + up, depth);
    const double w = width_of(out, l);
    const bool eyelet = l.stitch == yo && !decrease_at[static_cast<std::size_t>(l.course)].empty() &&
                        (l.shape == Template::knit || l.shape == Template::purl) &&
                        !(decreases(l.course, l.wale - 1) && decreases(l.course, l.wale + 1));
    for (int i = 0; i < loop_points; ++i) {
      glm::dvec3 p = plain[i];
      if (w != W) p.x *= w / W;
      if (eyelet && i > 0 && i < loop_points - 1) {
        p.y = H - (H - p.y) * eyelet_legs;
        p.z *= 0.5;
      }
      switch (l.shape) {
        case Template::knit: break;
        case Template::purl: p.z = -p.z; break;
        case Template::tuck:
          // Behind the loop it is held with, on the side the loop that knits both off comes
          // from (the face's back for a knit, its front for a purl), and a little below its
          // raised head, so the two heads never lie on one line seen from the face.
          // Level with it (its column not risen), the tuck's legs and feet would lie on
          // the held loop's seen from the face, its feet on theirs: the whole tuck lies
          // level_tuck_behind further back, its feet too.
          p.z = -0.35 * p.z - 0.6 * d * head[i];
          if (tucks[index] & level) p.z -= level_tuck_behind * d;
          if (tucks[index] & purled_off) p.z = -p.z;
          p.y -= 0.2 * d * head[i];
          break;
        case Template::rung:
          // The loop's yarn let out: straight across the wale in the fabric's plane, bowed
          // up a quarter course so that it clears the rung below.
          p = glm::dvec3(w * i / (loop_points - 1.0), rung_bow * C * std::sin(std::numbers::pi * i / (loop_points - 1.0)), 0.0);
          break;
        case Template::bind_off:
          p.y *= 0.85;
          p.z *= 0.8;
          p.x += 0.2 * W * head[i] * out.direction[l.course];
          break;
      }
      if (stitch(l.stitch).twisted && (l.shape == Template::knit || l.shape == Template::purl)) {
        p.x += twist_swap[i] * (w - 2.0 * p.x);
        p.z += twist_depth[i] * 0.55 * d;
      }
      // A cluster's loops, a fifth of a loop width each, alternate in depth so that
      // neighbours' legs do not lie on one line.
      if (w != W && stitch(l.stitch).cluster_width > 0.0)
        p.z += (l.wale % 2 ? 0.5 : -0.5) * d * std::sin(std::numbers::pi * i / (loop_points - 1.0));
      l.data_points[i] = origin + p;
    }
    // Exactly the next loop's P0, not origin + W rounded differently.
    l.data_points[loop_points - 1] = glm::dvec3(span.right, foot_y(out, l.course, l.wale) + up, depth);
    if (tucks[index] & level) l.data_points[loop_points - 1].z = l.data_points[0].z;  // its feet behind, both
  }
  // Where a course's yarn goes from one layer to the other, the two loops' shared end lies
  // between the layers: at each layer's depth, the yarn went straight through the fabric's
  // thickness there, a segment seen from the face as a point beside the heads of the loops
  // below, where which yarn crosses which is undecided (a double jacquard's colour changes:
  // mil-jacquard.k passed 438 crossings through, 85 so). Not in the cast-on course: a
  // pattern casts on with one yarn, where a machine may cast each bed on with its own
  // carrier, and the two carriers' loops share no end (a spacer so passed 19 through).
  for (std::size_t index = 0; index + 1 < out.loops.size(); ++index) {
    Loop &l = out.loops[index], &next = out.loops[index + 1];
    if (l.course == 0 || l.course != next.course || next.wale != l.wale + 1 || !layered(out, l.course)) continue;
    if (l.yarn != next.yarn || l.plating || next.plating) continue;  // two yarns' loops side by side share no end
    glm::dvec3& end = l.data_points[loop_points - 1];
    glm::dvec3& start = next.data_points[0];
    if (end.z != start.z) end.z = start.z = 0.5 * (end.z + start.z);
  }
}

// How far each cable loop leans (mm, its parent's centre less its own), 0 for others.
std::vector<double> cable_leans(const Layout& out, const std::vector<std::vector<int>>& parents) {
  std::vector<double> lean(out.loops.size(), 0.0);
  for (std::size_t i = 0; i < out.loops.size(); ++i) {
    const Loop& l = out.loops[i];
    if (parents[i].empty() || stitch(l.stitch).family != StitchFamily::cable) continue;
    const Loop& parent = out.loops[static_cast<std::size_t>(parents[i].front())];
    lean[i] = centre_x(out, parent.course, parent.wale) - centre_x(out, l.course, l.wale);
  }
  return lean;
}

// Each loop pulled through its parents. A cable's loop leans from its parent's head to
// its new needle position, passing in front of or behind the loops it crosses. Other
// loops meet their parents halfway: the parents' heads and the loop's legs, so that
// decreases gather with one parent on top; a parent whose child is more than one course
// up (slipped, tucked) is stretched up to it.
void pull_through(Layout& out, const Pattern& pattern, const std::vector<std::vector<int>>& parents,
                  const std::vector<double>& lean) {
  const double W = out.loop_width, C = out.course_spacing;
  const std::vector<char> bobbled = in_bobbles(out);
  auto leans_otherwise = [&](std::size_t i, std::size_t j) {  // j: i's neighbour in its course, if any
    const Loop &a = out.loops[i], &b = out.loops[j];
    return a.course != b.course || std::abs(a.wale - b.wale) != 1 || std::abs(lean[i] - lean[j]) > 1e-9;
  };
  for (std::size_t i = 0; i < out.loops.size(); ++i) {
    if (parents[i].empty() || bobbled[i]) continue;
    Loop& child = out.loops[i];
    const StitchDef& s = stitch(child.stitch);
    const double d = pattern.yarns[child.yarn].diameter;
    const double cx = centre_x(out, child.course, child.wale);
    if (s.family == StitchFamily::cable) {
      Loop& parent = out.loops[parents[i].front()];
      // In F cables the stitches moving left cross in front, in B those moving right; a
      // three-part cross's middle stays where it is.
      const bool travels = std::abs(lean[i]) >= 0.25 * W;
      const bool in_front = s.cable.front ? lean[i] > 0.0 : lean[i] < 0.0;
      const double dz = travels ? (in_front ? 0.6 : -0.6) * d : 0.0;
      // The whole way in the child's legs: its feet stay in the parent's head, which keeps
      // its place and only leans toward the side its child passes on. (Half the way in the
      // parent's head put the crossing parents' heads on one spot, 0.6 d apart in depth:
      // no room to relax.) The yarn between crossed feet runs behind the block.
      for (int j = 0; j < loop_points; ++j) {
        child.data_points[j] += glm::dvec3(feet[j] * lean[i], 0.0, crossing[j] * dz);
        parent.data_points[j] += head[j] * glm::dvec3(0.0, 0.0, 0.5 * dz);
      }
      const double short_of = (lean[i] > 0.0 ? -1.0 : 1.0) * crossed_sinker_gap * W;
      if (travels && (i == 0 || leans_otherwise(i, i - 1))) child.data_points[0].x += short_of;
      if (travels && (i + 1 == out.loops.size() || leans_otherwise(i, i + 1))) child.data_points[loop_points - 1].x += short_of;
      continue;
    }
    double mean = 0.0;
    for (int p : parents[i]) mean += centre_x(out, out.loops[p].course, out.loops[p].wale);
    mean /= static_cast<double>(parents[i].size());
    // The legs move at most 0.4 W (of their own width), or their sinker loops would double back on the
    // neighbours' (P15 lies 0.25 W inside P16); the parents' heads take the rest.
    const double reach = 0.4 * width_of(out, child);
    const double meet = cx + std::clamp(0.5 * (mean - cx), -reach, reach);
    for (std::size_t k = 0; k < parents[i].size(); ++k) {
      Loop& parent = out.loops[parents[i][k]];
      const double px = centre_x(out, parent.course, parent.wale);
      // A decrease's top head in front, the others behind it and a little lower (as a
      // tuck's is), or two gathered to one x lie on one line seen from the face, where
      // which crosses which is undecided.
      const bool gathered = s.family == StitchFamily::decrease && parents[i].size() > 1;
      const bool under = gathered && k != top_parent(s, parents[i].size());
      double dz = gathered ? (under ? -0.5 : 0.5) * d : 0.0;
      const double dy = under ? -gathered_drop * d : 0.0;
      // Three or more gathered (a double decrease, a nupp's five): the heads only halfway
      // to the meet, and the ones below the top alternating in depth, or they would lie on
      // one line (a k3tog's two lower heads on each other, parted either way by the
      // relaxation: 16 yarns through another in horseshoe lace, tests/lace_test.cpp).
      const bool many = gathered && parents[i].size() > 2;
      if (many && under) dz = (k % 2 ? -0.5 : -1.1) * d;
      const double up = !out.column_y.empty() ? foot_y(out, child.course, child.wale) - foot_y(out, parent.course, parent.wale) - C
                        : out.heights.empty() ? (child.course - parent.course - 1) * C
                                              : out.heights[child.course] - out.heights[parent.course] - C;
      const glm::dvec3 shift(many ? 0.5 * (meet - px) : meet - px, up + dy, dz);
      for (int j = 0; j < loop_points; ++j) parent.data_points[j] += head[j] * shift;
    }
    for (int j = 0; j < loop_points; ++j) child.data_points[j].x += legs[j] * (meet - cx);
  }
}

// A bobble stands out of the face: its rows are a strip bent round a ring across the
// course (in the y-z plane through its stitch), from just over the stitch below, down
// and out in front of it, up and over, and back to the fabric a little higher, where the
// loop that gathers the last row holds it. The strip's face (the legs) is outside, its
// sinker and needle loops on the ring; it fans out from the one stitch's width to
// 0.6 W a loop at the front. The gathering loop stands in its course with the foot the
// yarn enters by raised behind the last row's heads, whose yarn it comes from.
void shape_bobbles(Layout& out, const Pattern& pattern) {
  const auto plain = plain_loop(pattern.gauge);
  const double W = out.loop_width, C = out.course_spacing, H = pattern.gauge.loop_height, T = pattern.gauge.thickness;
  const double gap = std::numbers::pi / 4.0;  // the ring's open part, behind, between its ends
  for (const auto& b : out.bobbles) {
    const Loop& base = out.loops[static_cast<std::size_t>(b.first)];
    const double cx = centre_x(out, base.course, base.wale), y0 = foot_y(out, base.course, base.wale);
    const double end = (b.rows - 1) * C + H;  // along the ring: the last row's heads
    const double R = end / (2.0 * std::numbers::pi - gap);
    const double start = -0.5 * std::numbers::pi + 0.5 * gap;  // angle from straight down, turning out to the front
    const glm::dvec2 first(y0 + 0.05 * H, 0.2 * T);          // (y, z) of row 0's sinker loops
    const glm::dvec2 centre = first + R * glm::dvec2(std::cos(start), -std::sin(start));
    const double narrow = W, wide = 0.6 * W * b.loops;
    auto ring = [&](double along, double x_frac, double depth) {  // depth: out from the ring
      const double a = start + std::min(along, end) / R;
      const glm::dvec2 normal(-std::cos(a), std::sin(a));
      const glm::dvec2 p = centre + R * normal + depth * normal;
      const double width = narrow + (wide - narrow) * std::sin(std::numbers::pi * std::clamp(along / end, 0.0, 1.0));
      return glm::dvec3(cx + (x_frac - 0.5) * width, p.x, p.y);
    };
    for (int r = 0; r < b.rows; ++r)
      for (int k = 0; k < b.loops; ++k) {
        Loop& l = out.loops[static_cast<std::size_t>(b.first + r * b.loops + k)];
        for (int i = 0; i < loop_points; ++i) {
          const glm::dvec3& p = plain[static_cast<std::size_t>(i)];
          l.data_points[static_cast<std::size_t>(i)] = ring(r * C + p.y, (k + p.x / W) / b.loops, 0.7 * p.z);
        }
      }
    // The gathering loop: the foot it is entered by behind and below the last row's heads.
    Loop& top = out.loops[static_cast<std::size_t>(b.gathered())];
    const bool leftwards = out.direction[top.course] < 0;
    const int foot = leftwards ? loop_points - 1 : 0;
    const glm::dvec3 heads = ring(end, 0.5, 0.0);
    const glm::dvec3 raised(cx + (leftwards ? 0.3 : -0.3) * W, heads.y - 0.3 * H, heads.z - 0.5 * T);
    const glm::dvec3 move = raised - top.data_points[static_cast<std::size_t>(foot)];
    for (int i = 0; i < loop_points; ++i) {
      const int needle_loop = loop_points / 2;  // stays; the foot moves all the way
      const double weight = std::max(0.0, static_cast<double>(leftwards ? i - needle_loop : needle_loop - i) / needle_loop);
      top.data_points[static_cast<std::size_t>(i)] += weight * move;
    }
  }
}

// A wrapped group's last worked loop no longer shares its sinker point with the next
// loop: the yarn leaves it for the winding and comes back to the next, so its end is
// drawn in 0.12 W from the group's edge.
void part_wrapped_sinkers(Layout& out) {
  for (const auto& w : out.wraps) {
    const bool leftwards = out.direction[w.course] < 0;
    Loop& last = out.loops[static_cast<std::size_t>(leftwards ? w.first : w.last)];
    last.data_points[leftwards ? 0 : loop_points - 1].x += (leftwards ? 0.12 : -0.12) * out.loop_width;
  }
}

// The depth of a loop's left leg (P0..P8) at height y, or its P2's if y is off the leg.
double left_leg_z(const Loop& l, double y) {
  for (int k = 0; k + 1 <= loop_points / 2; ++k) {
    const glm::dvec3 &a = l.data_points[k], &b = l.data_points[k + 1];
    if ((y - a.y) * (y - b.y) <= 0.0 && std::abs(b.y - a.y) > 1e-12) return a.z + (b.z - a.z) * (y - a.y) / (b.y - a.y);
  }
  return l.data_points[2].z;
}

// Each caught float lifted into the loop that catches it: a little under its parent's
// head, in depth halfway between that head and the loop's legs, so that the float lies
// over the head and under the legs as the parent's own head does; from 0.45 W either side
// of the head's middle (outside the legs, between the heads of the course below). The
// floats one loop catches stack down from the head, the oldest lowest.
void lift_caught_floats(Layout& out, const Pattern& pattern, const std::vector<std::vector<int>>& parents) {
  out.float_lifts.assign(out.floats.size(), {});
  std::vector<int> caught(out.loops.size(), 0), placed(out.loops.size(), 0);
  for (const auto& f : out.floats)
    if (f.caught_by >= 0) ++caught[static_cast<std::size_t>(f.caught_by)];
  for (std::size_t i = 0; i < out.floats.size(); ++i) {
    const auto& f = out.floats[i];
    if (f.caught_by < 0) continue;
    const auto by = static_cast<std::size_t>(f.caught_by);
    const Loop& child = out.loops[by];
    assert(!parents[by].empty());
    const glm::dvec3 top = out.loops[static_cast<std::size_t>(parents[by].front())].data_points[loop_points / 2];
    const double d = pattern.yarns[static_cast<std::size_t>(f.yarn)].diameter;
    const int below = caught[by] - 1 - placed[by]++;  // floats in course order: the first is the lowest
    const double y = top.y - (0.5 + 0.9 * below) * d;
    const double z = 0.5 * (top.z + left_leg_z(child, y));
    const double W = out.loop_width;
    out.float_lifts[i] = {{top.x - 0.45 * W, y, z}, {top.x, y, z}, {top.x + 0.45 * W, y, z}};
  }
}

}  // namespace

Layout lay_out(const Pattern& pattern, const knit_graph::Graph& graph) {
  const bool bind_off = pattern.bound_off && !graph.live.empty();
  Layout out = frame_courses(pattern, graph, bind_off);
  out.loops.resize(graph.loops.size() + (bind_off ? graph.live.size() : 0));
  take_loops(out, graph);
  // The parents of every loop, the bind-off's too (the live stitches it works).
  std::vector<std::vector<int>> parents(out.loops.size());
  for (std::size_t i = 0; i < graph.loops.size(); ++i) parents[i] = graph.loops[i].parents;
  if (bind_off) add_bind_off(out, pattern, graph, parents);
  place_templates(out, pattern, tuck_lies(out, graph, parents));
  pull_through(out, pattern, parents, cable_leans(out, parents));
  shape_bobbles(out, pattern);
  lift_caught_floats(out, pattern, parents);
  part_wrapped_sinkers(out);
  return out;
}

}  // namespace knitc::layout
