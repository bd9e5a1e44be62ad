#include "layout/layout.hpp"

#include <cassert>

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
}  // namespace

std::span<const glm::dvec3, loop_points> plain_loop_fractions() { return table1; }

std::array<glm::dvec3, loop_points> plain_loop(const Gauge& g) {
  std::array<glm::dvec3, loop_points> p;
  const glm::dvec3 scale(g.loop_width, g.loop_height, g.thickness);
  for (int i = 0; i < loop_points; ++i) p[i] = table1[i] * scale;
  return p;
}

bool can_lay_out(StitchId id) {
  const StitchFamily f = stitch(id).family;
  return f == StitchFamily::knit || f == StitchFamily::purl;
}

Layout lay_out(const Pattern& pattern) {
  Layout layout;
  layout.courses = static_cast<int>(pattern.courses.size());
  const auto loop = plain_loop(pattern.gauge);
  const double W = pattern.gauge.loop_width, C = pattern.gauge.course_spacing();
  std::size_t total = 0;
  for (const Course& course : pattern.courses) total += course.ops.size();
  layout.loops.reserve(total);
  for (int c = 0; c < layout.courses; ++c) {
    const Course& course = pattern.courses[c];
    const int wales = static_cast<int>(course.ops.size());
    layout.wales = std::max(layout.wales, wales);
    for (int w = 0; w < wales; ++w) {
      Loop l;
      l.course = c;
      l.wale = w;
      assert(can_lay_out(course.ops[w].stitch));
      l.stitch = course.ops[w].stitch;
      l.yarn = course.ops[w].yarn;
      const double z = stitch(l.stitch).family == StitchFamily::purl ? -1.0 : 1.0;
      const glm::dvec3 origin(w * W, c * C, 0.0);
      for (int i = 0; i < loop_points; ++i) l.data_points[i] = origin + loop[i] * glm::dvec3(1.0, 1.0, z);
      // Exactly the next loop's P0, not origin + W rounded differently.
      l.data_points[loop_points - 1] = glm::dvec3((w + 1) * W, c * C, 0.0);
      layout.loops.push_back(l);
    }
  }
  return layout;
}

}  // namespace knitc::layout
