// Differential measures of a curve: curvature, torsion and arc length.
#include "nurbs.hpp"

#include <cassert>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

namespace knitc::nurbs {

double curvature(const Curve& c, double u) { return curvature(c, find_span(c, u), u); }

double curvature(const Curve& c, int span, double u) {
  const auto d = derivatives(c, span, u, 2);
  const double speed = glm::length(d[1]);
  if (speed == 0.0) return 0.0;
  return glm::length(glm::cross(d[1], d[2])) / (speed * speed * speed);
}

double Span::speed(double u) const { return glm::length(derivatives(u, 1)[1]); }

double Span::curvature(double u) const {
  const auto d = derivatives(u, 2);
  const double speed = glm::length(d[1]);
  if (speed == 0.0) return 0.0;
  return glm::length(glm::cross(d[1], d[2])) / (speed * speed * speed);
}

double torsion(const Curve& c, double u) {
  const auto d = derivatives(c, u, 3);
  const Point b = glm::cross(d[1], d[2]);
  const double b2 = glm::dot(b, b);
  if (b2 == 0.0) return 0.0;
  return glm::dot(b, d[3]) / b2;
}

namespace {

// 8-point Gauss-Legendre rule on [-1, 1].
constexpr double gl_x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                            -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                            0.7966664774136267,  0.9602898564975363};
constexpr double gl_w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                            0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                            0.2223810344533745, 0.1012285362903763};

double gauss_legendre(const Curve& c, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0.0;
  for (int i = 0; i < 8; ++i) sum += gl_w[i] * glm::length(derivatives(c, mid + half * gl_x[i], 1)[1]);
  return sum * half;
}

// The speed |C'| is smooth inside a knot span, so the rule converges fast there; halve
// until the two halves agree with the whole.
double adaptive(const Curve& c, double a, double b, double whole, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss_legendre(c, a, m), right = gauss_legendre(c, m, b);
  const double both = left + right;
  if (depth >= 30 || std::abs(both - whole) <= 1e-11 * std::max(both, 1e-300)) return both;
  return adaptive(c, a, m, left, depth + 1) + adaptive(c, m, b, right, depth + 1);
}

}  // namespace

namespace {

// The 5-point Gauss-Legendre rule over [a, b] inside one knot span, whose Span is kept in
// `span` from call to call (made anew when the rule leaves it).
double span_rule(const Curve& c, std::optional<Span>& span, double a, double b) {
  constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  constexpr double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                           0.2369268850561891};
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  // The rule's points lie inside one knot span; the steps ascend, so it is walked to.
  if (!span || !span->holds(mid)) span.emplace(c, span ? next_span(c, span->index(), mid) : find_span(c, mid));
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) sum += w[i] * span->speed(mid + half * x[i]);
  return sum * half;
}

double segment_length(const Curve& c, std::optional<Span>& span, double u0, double u1) {
  if (span && span->holds(u0) && u1 <= c.knots[static_cast<std::size_t>(span->index()) + 1]) return span_rule(c, span, u0, u1);
  // The speed is only C^(p-1) across a knot: one rule per knot span.
  double total = 0.0, a = u0;
  const int first = span ? next_span(c, span->index(), u0) : find_span(c, u0);
  for (std::size_t i = static_cast<std::size_t>(first) + 1; i < c.knots.size() && c.knots[i] < u1; ++i) {
    if (c.knots[i] <= a) continue;
    total += span_rule(c, span, a, c.knots[i]);
    a = c.knots[i];
  }
  return total + span_rule(c, span, a, u1);
}

}  // namespace

double segment_length(const Curve& c, double u0, double u1) {
  std::optional<Span> span;
  return segment_length(c, span, u0, u1);
}

void segment_lengths(const Curve& c, std::span<const double> u, std::span<double> out) {
  assert(out.size() + 1 == u.size());
  std::optional<Span> span;
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = segment_length(c, span, u[i], u[i + 1]);
}

double arc_length(const Curve& c, double u0, double u1) {
  if (!(u0 < u1)) return 0.0;
  double total = 0.0;
  // Integrate knot span by knot span: across a knot the speed is only C^(p-1).
  double a = u0;
  // From u0's own span: a course's curve has thousands of knots, a sample interval a few.
  for (std::size_t i = static_cast<std::size_t>(find_span(c, u0)) + 1; i < c.knots.size() && a < u1; ++i) {
    const double k = c.knots[i];
    if (k <= a) continue;
    const double b = std::min(k, u1);
    total += adaptive(c, a, b, gauss_legendre(c, a, b), 0);
    a = b;
  }
  return total;
}

}  // namespace knitc::nurbs
