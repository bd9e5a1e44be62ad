// The course layout: every loop of the knit graph placed as the seed paper's 17-point
// loop (Table 1) in its course and needle position, then moved by its stitch (pulled
// through its parents, leaning across for cables, gathered, held, stood out in a bobble).
// lay_out runs the passes in order, each working on the layout made so far: the courses'
// needle positions are courses.cpp's, the templates templates.cpp's, the pull through
// the parents pull_through.cpp's; the bind-off, the bobbles, the wraps and the caught
// floats are here (the loops' graph is knit_graph's).
#include "layout/layout.hpp"

#include "layout/courses.hpp"
#include "layout/passes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/vec2.hpp>

namespace knitc::layout {

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
  pull_through(out, pattern, parents);
  shape_bobbles(out, pattern);
  lift_caught_floats(out, pattern, parents);
  part_wrapped_sinkers(out);
  return out;
}

}  // namespace knitc::layout
