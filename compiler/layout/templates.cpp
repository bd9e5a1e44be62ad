// The loop templates: the seed paper's 17-point loop (Table 1) at each loop's needle
// position, shaped by its stitch (purl, tuck, ladder rung, bind-off, twisted, eyelet,
// plated, on its layer), before any loop is pulled through its parents (pull_through.cpp).
#include "layout/passes.hpp"

#include "layout/courses.hpp"

#include <cmath>
#include <limits>
#include <numbers>

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

// A twisted stitch (through the back loop): the lower legs change sides, the one from
// the left foot passing in front, so the loop is crossed on itself at its base.
constexpr std::array<double, loop_points> twist_swap = {0.0, 0.6, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0,
                                                        0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 0.6, 0.0};
constexpr std::array<double, loop_points> twist_depth = {0.0, 1.0, 1.0, 1.0, 0.6, 0.2, 0.0, 0.0, 0.0,
                                                         0.0, 0.0, 0.0, -0.2, -0.6, -1.0, -1.0, 0.0};

// A yarn over in lace has no parent to wrap its legs round: the strand lies over the
// needle, and the hole under it is the eyelet. Its loop is drawn with its legs this much
// of their length (the head where a plain loop's is, the feet on the course's line) and
// half as deep.
constexpr double eyelet_legs = 0.35;

// A ladder's rung rises this far (of C) at its middle.
constexpr double rung_bow = 0.25;

// How a tuck loop lies against the loop it is held with (both knitted off by one later
// loop), per loop: 0 for every loop but a tuck.
enum TuckLie : char {
  purled_off = 1,  // knitted off as a purl: the tuck lies on the face's side
  level = 2,       // its feet as high as the loop it is held with: its column did not rise
                   // for its course (an intarsia carrier's tuck on the next part's edge)
};

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

}  // namespace

std::span<const glm::dvec3, loop_points> plain_loop_fractions() { return table1; }

std::array<glm::dvec3, loop_points> plain_loop(const Gauge& g) {
  std::array<glm::dvec3, loop_points> p;
  const glm::dvec3 scale(g.loop_width, g.loop_height, g.thickness);
  for (int i = 0; i < loop_points; ++i) p[i] = table1[i] * scale;
  return p;
}

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
          p.z = -0.35 * p.z - 0.6 * d * head_weights[i];
          if (tucks[index] & level) p.z -= level_tuck_behind * d;
          if (tucks[index] & purled_off) p.z = -p.z;
          p.y -= 0.2 * d * head_weights[i];
          break;
        case Template::rung:
          // The loop's yarn let out: straight across the wale in the fabric's plane, bowed
          // up a quarter course so that it clears the rung below.
          p = glm::dvec3(w * i / (loop_points - 1.0), rung_bow * C * std::sin(std::numbers::pi * i / (loop_points - 1.0)), 0.0);
          break;
        case Template::bind_off:
          p.y *= 0.85;
          p.z *= 0.8;
          p.x += 0.2 * W * head_weights[i] * out.direction[l.course];
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

}  // namespace knitc::layout
