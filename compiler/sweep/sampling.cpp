#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "sweep/sweep.hpp"

namespace knitc::sweep {

namespace {

struct Cell {
  double a, b;     // parameter range
  double density;  // samples needed in the cell, fractional
};

// 3-point Gauss-Legendre estimate of arc length over [a, b]; cells are short and the
// estimate only sets sample density.
// span: the knot span holding [a, b).
double cell_length(const nurbs::Span& span, double a, double b) {
  constexpr double x = 0.7745966692414834, w0 = 8.0 / 9.0, w1 = 5.0 / 9.0;
  const double h = 0.5 * (b - a), m = 0.5 * (a + b);
  return h * (w1 * span.speed(m - h * x) + w0 * span.speed(m) + w1 * span.speed(m + h * x));
}

}  // namespace

std::vector<double> sample_parameters(const nurbs::Curve& c, double u0, double u1,
                                      double tolerance, double radius, double max_step) {
  constexpr int cells_per_span = 4;
  constexpr double max_samples = 1 << 22;  // a guard, far above any sane tolerance
  std::vector<Cell> cells;
  double a = u0;
  // A cell's end is the next one's start: its curvature is kept, not evaluated again
  // (the curvature is continuous across a knot: the span's end is the next's start).
  double last_u = NAN, last_k = 0.0;
  auto curvature = [&](const nurbs::Span& span, double u) {
    if (u != last_u) {
      last_u = u;
      last_k = span.curvature(u);
    }
    return last_k;
  };
  // [a, b) lies in one knot span, each after the last: found by walking, as find_span would.
  int at = nurbs::find_span(c, a);
  const int last_span = static_cast<int>(c.points.size()) - 1;
  auto add_span = [&](double b) {
    while (at < last_span && c.knots[static_cast<std::size_t>(at) + 1] <= a) ++at;
    assert(at == nurbs::find_span(c, a));
    const nurbs::Span span(c, at);
    for (int i = 0; i < cells_per_span; ++i) {
      const double ca = a + (b - a) * i / cells_per_span;
      const double cb = i + 1 == cells_per_span ? b : a + (b - a) * (i + 1) / cells_per_span;
      double k = std::max(0.0, curvature(span, ca));
      k = std::max(k, span.curvature(0.5 * (ca + cb)));
      k = std::max(k, curvature(span, cb));
      const double outer = k * (1.0 + radius * k);  // sagitta factor of the outer fibre
      const double step = outer > 0.0 ? std::sqrt(8.0 * tolerance / outer) : INFINITY;
      cells.push_back({ca, cb, cell_length(span, ca, cb) / std::min(step, max_step)});
    }
    a = b;
  };
  // Only the knots inside [u0, u1]: a course's curve has thousands, a loop a few.
  for (std::size_t i = static_cast<std::size_t>(nurbs::find_span(c, u0)) + 1; i < c.knots.size() && c.knots[i] < u1; ++i) {
    if (c.knots[i] > a) add_span(c.knots[i]);
  }
  add_span(u1);

  double total = 0.0;
  for (const Cell& cell : cells) total += cell.density;
  const int count = static_cast<int>(std::clamp(std::ceil(total), 1.0, max_samples));

  // Place sample j where the running density reaches j * total / count.
  std::vector<double> u;
  u.reserve(count + 1);
  u.push_back(u0);
  double before = 0.0;
  std::size_t i = 0;
  for (int j = 1; j < count; ++j) {
    const double target = total * j / count;
    while (i + 1 < cells.size() && before + cells[i].density < target) before += cells[i++].density;
    const Cell& cell = cells[i];
    const double f = cell.density > 0.0 ? std::clamp((target - before) / cell.density, 0.0, 1.0) : 1.0;
    const double s = cell.a + (cell.b - cell.a) * f;
    if (s > u.back() && s < u1) u.push_back(s);
  }
  u.push_back(u1);
  return u;
}

double estimate_samples(std::span<const glm::dvec3> points, double tolerance, double radius, double max_step) {
  // The density sample_parameters uses, with each point's curvature read off the circle
  // through it and its neighbours (Menger curvature) and each segment's length.
  double total = 1.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double length = glm::distance(points[i], points[i + 1]);
    double k = 0.0;
    for (std::size_t j : {i, i + 1}) {
      if (j == 0 || j + 1 >= points.size()) continue;
      const glm::dvec3 a = points[j - 1], b = points[j], c = points[j + 1];
      const double ab = glm::distance(a, b), bc = glm::distance(b, c), ca = glm::distance(c, a);
      if (ab <= 0.0 || bc <= 0.0 || ca <= 0.0) continue;
      k = std::max(k, 2.0 * glm::length(glm::cross(b - a, c - a)) / (ab * bc * ca));
    }
    const double outer = k * (1.0 + radius * k);
    const double step = outer > 0.0 ? std::sqrt(8.0 * tolerance / outer) : INFINITY;
    total += length / std::min(step, max_step);
  }
  return total;
}

}  // namespace knitc::sweep
