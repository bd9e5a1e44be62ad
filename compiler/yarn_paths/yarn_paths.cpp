#include "yarn_paths/yarn_paths.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace knitc::yarn_paths {

namespace {

using layout::Layout;

// The first point of a loop along the yarn, course-local.
glm::dvec3 entry(const Layout& layout, int index) {
  const layout::Loop& l = layout.loops[index];
  return l.data_points[layout::way(layout, static_cast<std::size_t>(index)) < 0 ? layout::loop_points - 1 : 0];
}

// Builds one piece, its points in course-local coordinates mapped to the fabric as they go.
struct PieceBuilder {
  const Layout& layout;
  Piece piece;
  glm::dvec3 last_local{0.0};  // the last point added, course-local
  int last_course = 0;
  int last_wale = 0;

  void add(const glm::dvec3& local, int course) {
    const glm::dvec3 p = layout::to_fabric(layout, local, course);
    // Never two equal points in a row, nor two all but equal: the interpolation needs
    // distinct parameters, and a curve through points a nanometre apart turns there in a
    // cusp its sampling cannot follow (a long float's last points, float_between below).
    if (!piece.data_points.empty() && glm::distance(piece.data_points.back(), p) < 1e-3) return;
    piece.data_points.push_back(p);
    last_local = local;
    last_course = course;
  }

  // Yarn lying straight from a to b (course-local, same course) at height z off the fabric,
  // a point about every loop width, each in the middle of its share, the ends themselves
  // not added. `a` is a copy: callers pass last_local, which each add() moves (taken by
  // reference, the shares compounded; docs/knitout.md, "Programs found elsewhere").
  void float_between(const glm::dvec3 a, const glm::dvec3& b, double z, int course) {
    const double W = layout.loop_width;
    const int n = std::max(1, static_cast<int>(std::lround(std::abs(b.x - a.x) / W)));
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) / n;
      glm::dvec3 p = a + t * (b - a);
      p.z = z;
      add(p, course);
    }
  }

  void add_loop(int index) {
    const layout::Loop& loop = layout.loops[index];
    const bool reversed = layout::way(layout, static_cast<std::size_t>(index)) < 0;
    // The yarn's first point on the loop is shared with the loop worked before, or a new one.
    const bool shared = !piece.data_points.empty() &&
                        glm::distance(layout::to_fabric(layout, entry(layout, index), loop.course), piece.data_points.back()) < 1e-9;
    piece.loop_first.push_back(shared ? piece.data_points.size() - 1 : piece.data_points.size());
    piece.loops.push_back(index);
    for (int k = shared ? 1 : 0; k < layout::loop_points; ++k)
      piece.data_points.push_back(layout::to_fabric(layout, loop.data_points[reversed ? layout::loop_points - 1 - k : k], loop.course));
    piece.loop_last.push_back(piece.data_points.size() - 1);
    last_local = loop.data_points[reversed ? 0 : layout::loop_points - 1];
    last_course = loop.course;
    last_wale = loop.wale;
  }

  // The yarn wound `turns` times round the loops [first, last] of a course after the last
  // of them is worked, from the edge the yarn left them at: across in front, back behind,
  // each turn a little higher up the loops' legs, ending beside that edge.
  void wind(const knit_graph::Wrap& w) {
    const double W = layout.loop_width, C = layout.course_spacing;
    const double left = layout.loops[static_cast<std::size_t>(w.first)].data_points.front().x;
    const double right = layout.loops[static_cast<std::size_t>(w.last)].data_points.back().x;
    const double way = layout.direction[w.course] < 0 ? 1.0 : -1.0;  // from the exit edge across the group
    const double near = way > 0 ? left : right, far = way > 0 ? right : left;
    const double y0 = layout::foot_y(layout, w.course, layout.loops[static_cast<std::size_t>(w.first)].wale);
    const int across = std::max(1, static_cast<int>(std::lround((right - left) / (0.5 * W))));
    auto pass = [&](double from, double to, double y, double z) {
      for (int k = 0; k <= across; ++k) add({from + (to - from) * k / across, y, z}, w.course);
    };
    for (int t = 0; t < w.turns; ++t) {
      const double y = y0 + (0.4 + 0.3 * t) * C;
      // Out beside the group: toward the front on the way in, behind on the way back
      // down, so that the two never cross at one depth.
      add({near - way * 0.15 * W, y, t == 0 ? 0.4 * layout.float_in_front : 0.0}, w.course);
      pass(near, far, y + 0.05 * C, layout.float_in_front);
      add({far + way * 0.15 * W, y + 0.1 * C, 0.0}, w.course);
      pass(far, near, y + 0.15 * C, layout.float_behind);
    }
    add({near - way * 0.15 * W, y0 + 0.25 * C, 0.4 * layout.float_behind}, w.course);
  }

  // A short end of yarn behind the fabric, leaving `at` along x in direction `way`.
  std::vector<glm::dvec3> tail(const glm::dvec3& at, double way) const {
    const double W = layout.loop_width, C = layout.course_spacing, z = layout.float_behind;
    return {at + glm::dvec3(way * 0.45 * W, 0.15 * C, 0.5 * z), at + glm::dvec3(way * 1.1 * W, 0.05 * C, z)};
  }
};

// The slip-stitch float of this yarn that covers x0..x1 of the course: its index into
// layout.floats, or -1 (the yarn passes behind, as stranded work's does).
int float_over(const Layout& layout, int course, int yarn, double x0, double x1) {
  // The graph lists floats course by course: only this course's are looked at.
  const auto by_course = [](const knit_graph::Float& f, int c) { return f.course < c; };
  for (auto f = std::lower_bound(layout.floats.begin(), layout.floats.end(), course, by_course);
       f != layout.floats.end() && f->course == course; ++f) {
    if (f->yarn != yarn) continue;
    const auto& edges = layout.slot_x[static_cast<std::size_t>(course)];
    const double a = edges[static_cast<std::size_t>(f->first)], b = edges[static_cast<std::size_t>(f->last) + 1];
    if (std::min(x0, x1) < b - 1e-9 && std::max(x0, x1) > a + 1e-9) return static_cast<int>(f - layout.floats.begin());
  }
  return -1;
}

std::vector<Piece> trace_smooth(const Layout& layout) {
  const double W = layout.loop_width;
  int yarns = 0;
  for (const layout::Loop& l : layout.loops) yarns = std::max(yarns, l.yarn + 1);
  std::vector<std::vector<int>> along(yarns);
  for (std::size_t i = 0; i < layout.loops.size(); ++i) along[layout.loops[i].yarn].push_back(static_cast<int>(i));
  // The loop each winding follows along the yarn: its group's last worked, at the edge
  // the course's work leaves it by.
  std::vector<int> wrap_after(layout.loops.size(), -1);
  for (std::size_t i = 0; i < layout.wraps.size(); ++i) {
    const auto& w = layout.wraps[i];
    wrap_after[static_cast<std::size_t>(layout.direction[w.course] < 0 ? w.first : w.last)] = static_cast<int>(i);
  }
  const std::vector<char> bobbled = layout::in_bobbles(layout);
  std::vector<Piece> pieces;
  for (int y = 0; y < yarns; ++y) {
    auto& order = along[y];
    std::sort(order.begin(), order.end(), [&](int a, int b) { return layout.loops[a].order < layout.loops[b].order; });
    PieceBuilder b{layout, {}, {}, 0, 0};
    auto finish = [&] {
      if (b.piece.loops.empty()) return;
      const int c = b.last_course;
      for (const auto& p : b.tail(b.last_local, layout.direction[c])) b.add(p, c);
      pieces.push_back(std::move(b.piece));
      b.piece = {};
    };
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int index = order[k];
      const int course = layout.loops[index].course;
      const glm::dvec3 start = entry(layout, index);
      if (b.piece.loops.empty()) {
        b.piece.yarn = y;
      } else if (course == b.last_course && bobbled[static_cast<std::size_t>(index)] && k > 0 &&
                 bobbled[static_cast<std::size_t>(order[k - 1])]) {
        // On through a bobble: turned at its edge, or up into the loop gathering it.
      } else if (course == b.last_course) {
        // Needle positions passed by within the course, or a cable's sinker loop crossing
        // behind it: a float, behind unless slipped wyif.
        // Two layers: the other layer's positions are not passed by, and a float runs
        // between the layers.
        const bool layered = layout::layered(layout, course);
        if ((!layered && std::abs(layout.loops[index].wale - b.last_wale) > 1) || std::abs(start.x - b.last_local.x) > 0.5 * W) {
          const int f = float_over(layout, course, y, b.last_local.x, start.x);
          double z = f >= 0 && layout.floats[static_cast<std::size_t>(f)].in_front ? layout.float_in_front : layout.float_behind;
          if (layered) z = 0.0;
          const auto* lift = f >= 0 && !layout.float_lifts.empty() ? &layout.float_lifts[static_cast<std::size_t>(f)] : nullptr;
          if (lift && !lift->empty()) {
            // Caught: up to the loop that lifts it and back down, through its lift points
            // in the order the yarn goes.
            const bool rightwards = start.x > b.last_local.x;
            const glm::dvec3 first = rightwards ? lift->front() : lift->back(), last = rightwards ? lift->back() : lift->front();
            b.float_between(b.last_local, first, z, course);
            for (std::size_t p = 0; p < lift->size(); ++p) b.add((*lift)[rightwards ? p : lift->size() - 1 - p], course);
            b.float_between(last, start, z, course);
          } else {
            b.float_between(b.last_local, start, z, course);
          }
        } else if (!layout.column_y.empty() && std::abs(start.y - b.last_local.y) > 0.5 * layout.course_spacing) {
          // A step where short rows left the columns at different heights: the yarn climbs
          // behind the fabric from one loop's end to the next, not straight along the
          // columns' edge, over the sinker loops of the courses below the taller one
          // (there, which yarn crosses which was undecided: a wedge of 24 stitches and 12
          // short rows passed 11 of its 2,393 crossings through relaxed, none so).
          glm::dvec3 mid = 0.5 * (b.last_local + start);
          mid.z = layout.float_behind;
          b.add(mid, course);
        }
      } else if (course == b.last_course + 1) {
        const glm::dvec3 a = b.last_local;
        const int from = b.last_course;
        if (layout.knitting == Knitting::round) {
          // Round the tube: in this course's coordinates the next round starts a turn to the
          // left. But where it starts nearer straight up, the yarn goes there, not a turn
          // round the tube (a chain bind-off knits one needle three times, each a course of
          // one loop: a turn each drew a float all round the tube's top).
          glm::dvec3 next = start;
          next.x -= layout::course_width(layout, course);
          next.y -= layout.course_spacing;
          if (std::abs(a.x - start.x) < std::abs(a.x - next.x)) {
            if (std::abs(a.x - start.x) > 0.5 * W) b.float_between(a, start, layout.float_behind, from);
          } else if (std::abs(a.x - next.x) > 0.5 * W) {
            b.float_between(a, next, layout.float_behind, from);
          }
        } else if (layout.direction[from] != layout.direction[course]) {
          // Turn at the selvedge the row ended at, floating behind to it if the yarn's last
          // or next loop is not at the edge (stranded work).
          const double way = layout.direction[from];
          const double edge = way < 0 ? std::min(a.x, start.x) : std::max(a.x, start.x);
          const glm::dvec3 a_edge(edge, a.y, a.z), start_edge(edge, start.y, start.z);
          if (std::abs(a.x - edge) > 0.5 * W) b.float_between(a, a_edge, layout.float_behind, from);
          const double out = edge + way * 0.4 * W;
          b.add({out, a.y + 0.3 * (start.y - a.y), 0.0}, from);
          b.add({out, a.y + 0.7 * (start.y - a.y), 0.0}, from);
          if (std::abs(start.x - edge) > 0.5 * W) b.float_between(start_edge, start, layout.float_behind, course);
        } else {
          b.float_between(a, start, layout.float_behind, from);  // the yarn slid back along the row
        }
      } else {
        finish();  // the yarn is cut: courses without it in between
        b.piece.yarn = y;
      }
      if (b.piece.loops.empty()) {
        const auto t = b.tail(start, -layout.direction[course]);
        b.add(t[1], course);
        b.add(t[0], course);
      }
      b.add_loop(index);
      if (wrap_after[static_cast<std::size_t>(index)] >= 0) b.wind(layout.wraps[static_cast<std::size_t>(wrap_after[static_cast<std::size_t>(index)])]);
    }
    finish();
  }
  return pieces;
}

}  // namespace

std::vector<Piece> trace(const Layout& layout, LoopModel model) {
  if (model == LoopModel::smooth) return trace_smooth(layout);
  std::vector<Piece> pieces;
  pieces.reserve(layout.loops.size());
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const layout::Loop& l = layout.loops[i];
    Piece p;
    p.yarn = l.yarn;
    p.loops = {static_cast<int>(i)};
    p.loop_first = {0};
    p.loop_last = {points_per_loop};
    for (const auto& q : l.data_points) p.data_points.push_back(layout::to_fabric(layout, q, l.course));
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace knitc::yarn_paths
