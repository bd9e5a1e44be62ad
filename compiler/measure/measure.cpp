#include "measure/measure.hpp"

#include "spatial/columns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace knitc::measure {

namespace {

struct Point {
  glm::dvec3 at;
  double along;  // mm from the piece's start
  double radius;  // mm: the free radius
  double core;    // mm: the core radius
  std::uint32_t piece;
};

// The centrelines as points no more than a quarter diameter apart, and none within a
// 256th of a diameter of the one before: samples piled up in one place (a curve through
// data points a nanometre apart was sampled 3 million times in one span) would fill one
// cell, and the search below compares a cell's points pair by pair.
std::vector<Point> centreline_points(const Pattern& pattern, std::span<const curves::CurvePiece> pieces) {
  std::vector<Point> points;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const curves::CurvePiece& p = pieces[i];
    const double d = pattern.yarns[p.path.yarn].diameter, core = 0.5 * pattern.yarns[p.path.yarn].core_diameter;
    const auto& o = p.frames.origin;
    const std::size_t first = points.size();
    auto add = [&](const glm::dvec3& at, double along) {
      if (points.size() > first && glm::distance(points.back().at, at) < d / 256.0) return;
      points.push_back({at, along, 0.5 * d, core, static_cast<std::uint32_t>(i)});
    };
    for (std::size_t s = 0; s < o.size(); ++s) {
      if (s > 0) {
        const double step = glm::distance(o[s - 1], o[s]);
        const int n = static_cast<int>(std::ceil(step / (0.25 * d)));
        for (int k = 1; k < n; ++k) {
          const double t = static_cast<double>(k) / n;
          add(o[s - 1] + t * (o[s] - o[s - 1]), p.arc_length[s - 1] + t * (p.arc_length[s] - p.arc_length[s - 1]));
        }
      }
      add(o[s], p.arc_length[s]);
    }
  }
  return points;
}

// Cells one diameter (`cell`, the thickest yarn's) wide; overlaps per that diameter, of
// the free radii and of the cores (per `thickest_core`). Pairs of one piece closer than
// two free diameters along it are one stretch of yarn, not a contact.
struct Penetration {
  double free = 0.0, core = 0.0;
};
Penetration deepest_penetration(const std::vector<Point>& points, double cell, double thickest_core) {
  if (points.empty()) return {};
  spatial::Columns grid(cell);
  grid.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) grid.add(grid.cell_of(points[i].at), static_cast<std::uint32_t>(i));
  grid.index();
  Penetration deepest;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& a = points[i];
    grid.near(grid.cell_of(a.at), [&](const spatial::Columns::Entry& e) {
      if (e.item <= i) return;
      const Point& b = points[e.item];
      const double reach = a.radius + b.radius;
      if (a.piece == b.piece && std::abs(a.along - b.along) <= 2.0 * reach) return;
      const double gap = glm::distance(a.at, b.at);
      if (gap < reach) deepest.free = std::max(deepest.free, (reach - gap) / cell);
      if (gap < a.core + b.core) deepest.core = std::max(deepest.core, (a.core + b.core - gap) / thickest_core);
    });
  }
  return deepest;
}

}  // namespace

FabricMeasures measure(const Pattern& pattern, const layout::Layout& layout, std::span<const curves::CurvePiece> pieces) {
  FabricMeasures m;
  m.loops = layout.loops.size();
  m.pieces = pieces.size();
  m.yarn_length.assign(pattern.yarns.size(), 0.0);
  double thickest = 0.0, thickest_core = 0.0;
  for (const Yarn& y : pattern.yarns) {
    thickest = std::max(thickest, y.diameter);
    thickest_core = std::max(thickest_core, y.core_diameter);
  }
  m.tightest_bend = std::numeric_limits<double>::infinity();
  for (const curves::CurvePiece& p : pieces) {
    if (!p.arc_length.empty()) m.yarn_length[p.path.yarn] += p.arc_length.back();
    const double radius = 0.5 * pattern.yarns[p.path.yarn].diameter;
    for (std::size_t s = 0; s < p.samples.size(); ++s) {
      const double k = nurbs::curvature(p.curve.curve, p.samples[s]);
      if (k > 0.0) m.tightest_bend = std::min(m.tightest_bend, 1.0 / (k * radius));
      if (s > 0) {
        const double c = std::clamp(glm::dot(p.frames.normal[s - 1], p.frames.normal[s]), -1.0, 1.0);
        const double t = std::clamp(glm::dot(p.frames.tangent[s - 1], p.frames.tangent[s]), -1.0, 1.0);
        m.largest_frame_turn = std::max(m.largest_frame_turn, std::acos(std::min(c, t)) * 180.0 / std::numbers::pi);
      }
    }
  }
  // Distances are compared against each pair's radii; the overlap is reported per
  // diameter of the thickest yarn (one yarn in most fabrics).
  if (thickest > 0.0 && thickest_core > 0.0) {
    const Penetration p = deepest_penetration(centreline_points(pattern, pieces), thickest, thickest_core);
    m.deepest_penetration = p.free;
    m.deepest_core_penetration = p.core;
  }
  return m;
}

LoopShape loop_shape(const layout::Layout& layout, std::span<const curves::CurvePiece> pieces) {
  // Each loop's centre and length, from the piece that owns it.
  std::vector<glm::dvec3> centre(layout.loops.size(), glm::dvec3(0.0));
  std::vector<double> length(layout.loops.size(), -1.0);
  std::vector<glm::dvec2> depth(layout.loops.size(), glm::dvec2(1e300, -1e300));  // z from, to
  for (const curves::CurvePiece& p : pieces) {
    for (std::size_t j = 0; j < p.path.loops.size() && j < p.loop_samples.size(); ++j) {
      const auto [first, last] = p.loop_samples[j];
      glm::dvec3 sum(0.0);
      const auto loop = static_cast<std::size_t>(p.path.loops[j]);
      for (std::size_t s = first; s <= last; ++s) {
        sum += p.frames.origin[s];
        depth[loop] = glm::dvec2(std::min(depth[loop].x, p.frames.origin[s].z), std::max(depth[loop].y, p.frames.origin[s].z));
      }
      centre[loop] = sum / static_cast<double>(last - first + 1);
      length[loop] = p.arc_length[last] - p.arc_length[first];
    }
  }
  // The loop at (course, needle position), if any.
  std::vector<std::size_t> course_first(static_cast<std::size_t>(layout.courses) + 1, layout.loops.size());
  for (std::size_t i = layout.loops.size(); i-- > 0;) course_first[static_cast<std::size_t>(layout.loops[i].course)] = i;
  for (std::size_t c = course_first.size() - 1; c-- > 0;) course_first[c] = std::min(course_first[c], course_first[c + 1]);
  auto at = [&](int course, int wale) -> long {  // a course's loops are left to right
    if (course < 0 || course >= layout.courses) return -1;
    const auto first = layout.loops.begin() + static_cast<std::ptrdiff_t>(course_first[static_cast<std::size_t>(course)]);
    const auto last = layout.loops.begin() + static_cast<std::ptrdiff_t>(course_first[static_cast<std::size_t>(course) + 1]);
    const auto it = std::lower_bound(first, last, wale, [](const layout::Loop& l, int w) { return l.wale < w; });
    return it != last && it->wale == wale ? static_cast<long>(it - layout.loops.begin()) : -1;
  };
  LoopShape shape;
  double wales = 0.0, courses = 0.0, across = 0.0, up_pitch = 0.0;
  double z_from = 1e300, z_to = -1e300;
  std::size_t wale_pairs = 0, course_pairs = 0;
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const auto& l = layout.loops[i];
    const int needles = layout.needle[static_cast<std::size_t>(l.course)];
    if (l.course < 2 || l.course > layout.courses - 3 || l.wale < 2 || l.wale > needles - 3 || length[i] < 0.0) continue;
    const long right = at(l.course, l.wale + 1), up = at(l.course + 1, l.wale);
    if (right < 0 || up < 0 || length[static_cast<std::size_t>(right)] < 0.0 || length[static_cast<std::size_t>(up)] < 0.0) continue;
    ++shape.loops;
    shape.loop_length += length[i];
    wales += glm::distance(centre[i], centre[static_cast<std::size_t>(right)]);
    across += std::abs(centre[static_cast<std::size_t>(right)].x - centre[i].x);
    ++wale_pairs;
    courses += glm::distance(centre[i], centre[static_cast<std::size_t>(up)]);
    up_pitch += std::abs(centre[static_cast<std::size_t>(up)].y - centre[i].y);
    z_from = std::min(z_from, depth[i].x);
    z_to = std::max(z_to, depth[i].y);
    ++course_pairs;
  }
  if (shape.loops == 0) return shape;
  shape.loop_length /= static_cast<double>(shape.loops);
  shape.wale_spacing = wales / static_cast<double>(wale_pairs);
  shape.course_spacing = courses / static_cast<double>(course_pairs);
  shape.wale_pitch = across / static_cast<double>(wale_pairs);
  shape.course_pitch = up_pitch / static_cast<double>(course_pairs);
  shape.depth = z_to - z_from;
  shape.kc = shape.loop_length / shape.course_spacing;
  shape.kw = shape.loop_length / shape.wale_spacing;
  return shape;
}

}  // namespace knitc::measure
