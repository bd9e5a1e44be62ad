// Helpers shared by the NURBS tests: seeded point clouds, error bookkeeping, spans.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <gtest/gtest.h>

#include "nurbs/nurbs.hpp"
#include "reference_nurbs.hpp"


namespace knitc::nurbs_test {

using nurbs::Curve;
using nurbs::InterpolationOptions;
using nurbs::Parametrisation;
using nurbs::Point;

constexpr Parametrisation both_parametrisations[] = {Parametrisation::chord_length, Parametrisation::centripetal};

inline const char* name(Parametrisation p) { return p == Parametrisation::centripetal ? "centripetal" : "chord length"; }

// The largest of a batch of (relative) errors, and a description of where it happened.
struct Worst {
  double error = 0.0;
  std::string where;
  template <class Describe>
  void add(double e, const Describe& describe) {
    if (std::isnan(error)) return;  // keep the first NaN: it fails every comparison
    if (e > error || std::isnan(e)) {
      error = e;
      where = describe();
    }
  }
};

inline std::string str(const Point& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

inline double uniform(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// `count` points uniformly in the cube offset + [-size, size]^3.
inline std::vector<Point> random_cloud(std::mt19937& rng, int count, double size = 1.0, Point offset = Point(0.0)) {
  std::vector<Point> q;
  for (int k = 0; k < count; ++k)
    q.push_back(offset + size * Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
  return q;
}

// A wandering path: steps of length 0.05..1 whose direction turns by a random amount,
// closer to the yarn centrelines the compiler interpolates than a point cloud.
inline std::vector<Point> random_walk(std::mt19937& rng, int count) {
  std::vector<Point> q{Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1))};
  Point dir = glm::normalize(Point(1.0, 0.3, -0.2));
  while (static_cast<int>(q.size()) < count) {
    dir = glm::normalize(dir + 1.2 * Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
    q.push_back(q.back() + uniform(rng, 0.05, 1.0) * dir);
  }
  return q;
}

// The scale relative errors of point-like quantities are measured against.
inline double magnitude(const std::vector<Point>& q) {
  double m = 0.0;
  for (const auto& p : q) m = std::max(m, glm::length(p));
  return m;
}

inline nurbs::Interpolant interpolate(const std::vector<Point>& q, Parametrisation par) {
  InterpolationOptions o;
  o.parametrisation = par;
  return nurbs::interpolate(q, o);
}

// A valid random clamped curve on the domain [lo, hi]: random interior knots, each of
// multiplicity 1..max_multiplicity, random control points and (if rational) weights in
// [0.3, 3].
inline Curve random_curve(std::mt19937& rng, int degree, int count, bool rational, int max_multiplicity, double lo = 0.0,
                   double hi = 1.0) {
  Curve c;
  c.degree = degree;
  const int interior = count - degree - 1;
  std::vector<double> inner;
  while (static_cast<int>(inner.size()) < interior) {
    const double k = uniform(rng, lo, hi);
    const int mult = std::min(interior - static_cast<int>(inner.size()),
                              std::uniform_int_distribution<int>(1, max_multiplicity)(rng));
    for (int m = 0; m < mult; ++m) inner.push_back(k);
  }
  std::sort(inner.begin(), inner.end());
  c.knots.assign(static_cast<std::size_t>(degree) + 1, lo);
  c.knots.insert(c.knots.end(), inner.begin(), inner.end());
  c.knots.insert(c.knots.end(), static_cast<std::size_t>(degree) + 1, hi);
  c.points = random_cloud(rng, count);
  if (rational)
    for (int i = 0; i < count; ++i) c.weights.push_back(uniform(rng, 0.3, 3.0));
  return c;
}

// Like random_curve with simple interior knots whose gaps differ by at most a factor of
// three, so that no knot span is tiny: for finite-difference checks.
inline Curve random_even_curve(std::mt19937& rng, int degree, int count, bool rational) {
  Curve c = random_curve(rng, degree, count, rational, 1);
  const int spans = count - degree;
  std::vector<double> gaps;
  double total = 0.0;
  for (int s = 0; s < spans; ++s) total += gaps.emplace_back(uniform(rng, 1.0, 3.0));
  double acc = 0.0;
  for (int s = 1; s < spans; ++s) {
    acc += gaps[static_cast<std::size_t>(s - 1)];
    c.knots[static_cast<std::size_t>(degree + s)] = acc / total;
  }
  return c;
}

// The non-empty knot spans [a, b] of a curve.
inline std::vector<std::pair<double, double>> spans_of(const Curve& c) {
  std::vector<std::pair<double, double>> s;
  for (std::size_t i = 0; i + 1 < c.knots.size(); ++i)
    if (c.knots[i] < c.knots[i + 1]) s.emplace_back(c.knots[i], c.knots[i + 1]);
  return s;
}

// The span index by linear search: the i with knots[i] <= u < knots[i+1], u clamped to the
// domain, the last non-empty span at the domain's end.
inline int span_by_search(const Curve& c, double u) {
  const auto& U = c.knots;
  const int n = static_cast<int>(c.points.size()) - 1;
  u = std::clamp(u, U.front(), U.back());
  if (u == U.back()) {
    for (int i = n; i >= c.degree; --i)
      if (U[static_cast<std::size_t>(i)] < U[static_cast<std::size_t>(i) + 1]) return i;
  }
  for (int i = c.degree; i <= n; ++i)
    if (U[static_cast<std::size_t>(i)] <= u && u < U[static_cast<std::size_t>(i) + 1]) return i;
  return -1;
}

// The parameter values to probe a curve at: every knot, the ends, and random values.
inline std::vector<double> probe_parameters(std::mt19937& rng, const Curve& c, int random_count) {
  std::vector<double> u(c.knots.begin(), c.knots.end());
  for (int k = 0; k < random_count; ++k) u.push_back(uniform(rng, c.knots.front(), c.knots.back()));
  return u;
}


// The cubic Bezier of control points P at u, in Bernstein form.
inline Point bernstein(const Point P[4], double u) {
  const double v = 1 - u;
  return v * v * v * P[0] + 3 * u * v * v * P[1] + 3 * u * u * v * P[2] + u * u * u * P[3];
}

// A quarter of the unit circle as a rational quadratic.
inline Curve quarter_circle() {
  Curve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.points = {Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  c.weights = {1, std::numbers::sqrt2 / 2, 1};
  return c;
}

}  // namespace knitc::nurbs_test
