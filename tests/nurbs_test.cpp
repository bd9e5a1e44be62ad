// Unit tests of the NURBS core (compiler/nurbs/): find_span, the basis functions and
// their derivatives (partition of unity, non-negativity, derivative rows summing to
// zero, agreement with the Cox-de Boor recursion), curve derivatives against central
// differences and against reference_nurbs.hpp, a Bezier curve checked by hand, rational
// circles (on the circle, curvature, torsion, arc length), curvature and torsion of an
// interpolated helix, arc length of lines and its additivity, and interpolation: through
// every data point, invariant under similarity transforms, with end derivatives, equal to
// the independent dense implementation in reference_nurbs.hpp, and rejecting bad input.
// Random data comes from std::mt19937 with fixed seeds, so every run is the same.
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

namespace knitc {
namespace {

using nurbs::Curve;
using nurbs::InterpolationOptions;
using nurbs::Parametrisation;
using nurbs::Point;

constexpr Parametrisation both_parametrisations[] = {Parametrisation::chord_length, Parametrisation::centripetal};

const char* name(Parametrisation p) { return p == Parametrisation::centripetal ? "centripetal" : "chord length"; }

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

std::string str(const Point& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

double uniform(std::mt19937& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// `count` points uniformly in the cube offset + [-size, size]^3.
std::vector<Point> random_cloud(std::mt19937& rng, int count, double size = 1.0, Point offset = Point(0.0)) {
  std::vector<Point> q;
  for (int k = 0; k < count; ++k)
    q.push_back(offset + size * Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
  return q;
}

// A wandering path: steps of length 0.05..1 whose direction turns by a random amount,
// closer to the yarn centrelines the compiler interpolates than a point cloud.
std::vector<Point> random_walk(std::mt19937& rng, int count) {
  std::vector<Point> q{Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1))};
  Point dir = glm::normalize(Point(1.0, 0.3, -0.2));
  while (static_cast<int>(q.size()) < count) {
    dir = glm::normalize(dir + 1.2 * Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
    q.push_back(q.back() + uniform(rng, 0.05, 1.0) * dir);
  }
  return q;
}

// The scale relative errors of point-like quantities are measured against.
double magnitude(const std::vector<Point>& q) {
  double m = 0.0;
  for (const auto& p : q) m = std::max(m, glm::length(p));
  return m;
}

nurbs::Interpolant interpolate(const std::vector<Point>& q, Parametrisation par) {
  InterpolationOptions o;
  o.parametrisation = par;
  return nurbs::interpolate(q, o);
}

// A valid random clamped curve on the domain [lo, hi]: random interior knots, each of
// multiplicity 1..max_multiplicity, random control points and (if rational) weights in
// [0.3, 3].
Curve random_curve(std::mt19937& rng, int degree, int count, bool rational, int max_multiplicity, double lo = 0.0,
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
Curve random_even_curve(std::mt19937& rng, int degree, int count, bool rational) {
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
std::vector<std::pair<double, double>> spans_of(const Curve& c) {
  std::vector<std::pair<double, double>> s;
  for (std::size_t i = 0; i + 1 < c.knots.size(); ++i)
    if (c.knots[i] < c.knots[i + 1]) s.emplace_back(c.knots[i], c.knots[i + 1]);
  return s;
}

// The span index by linear search: the i with knots[i] <= u < knots[i+1], u clamped to the
// domain, the last non-empty span at the domain's end.
int span_by_search(const Curve& c, double u) {
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
std::vector<double> probe_parameters(std::mt19937& rng, const Curve& c, int random_count) {
  std::vector<double> u(c.knots.begin(), c.knots.end());
  for (int k = 0; k < random_count; ++k) u.push_back(uniform(rng, c.knots.front(), c.knots.back()));
  return u;
}

// ---------------------------------------------------------------------------------------
// find_span

TEST(NurbsFindSpan, HandPickedKnotVectorIncludingTheEnd) {
  Curve c;
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1, 1};
  c.points.assign(8, Point(0.0));
  ASSERT_TRUE(nurbs::is_valid(c));
  EXPECT_EQ(nurbs::find_span(c, 0.0), 3);
  EXPECT_EQ(nurbs::find_span(c, 0.1), 3);
  EXPECT_EQ(nurbs::find_span(c, 0.25), 4);
  EXPECT_EQ(nurbs::find_span(c, 0.3), 4);
  EXPECT_EQ(nurbs::find_span(c, std::nextafter(0.5, 0.0)), 4);
  EXPECT_EQ(nurbs::find_span(c, 0.5), 6);  // the double knot: U[6] <= u < U[7]
  EXPECT_EQ(nurbs::find_span(c, 0.6), 6);
  EXPECT_EQ(nurbs::find_span(c, 0.75), 7);
  EXPECT_EQ(nurbs::find_span(c, 0.9), 7);
  EXPECT_EQ(nurbs::find_span(c, std::nextafter(1.0, 0.0)), 7);
  EXPECT_EQ(nurbs::find_span(c, 1.0), 7);  // the domain's end: the last non-empty span
  EXPECT_EQ(nurbs::find_span(c, -0.5), 3);  // clamped
  EXPECT_EQ(nurbs::find_span(c, 1.5), 7);   // clamped
}

TEST(NurbsFindSpan, MatchesLinearSearchOnRandomKnotVectors) {
  std::mt19937 rng(101);
  for (int trial = 0; trial < 300; ++trial) {
    const int p = 1 + trial % 7;
    const int count = p + 1 + std::uniform_int_distribution<int>(0, 30)(rng);
    const double lo = uniform(rng, -3, 1), hi = lo + uniform(rng, 0.5, 4);
    const Curve c = random_curve(rng, p, count, false, p, lo, hi);
    ASSERT_TRUE(nurbs::is_valid(c));
    auto us = probe_parameters(rng, c, 50);
    us.push_back(lo - 1.0);
    us.push_back(hi + 1.0);
    for (const double u : us) {
      const int span = nurbs::find_span(c, u);
      ASSERT_EQ(span, span_by_search(c, u)) << "degree " << p << ", " << count << " points, u = " << u;
      // The span is non-empty and holds (the clamped) u.
      const double uc = std::clamp(u, lo, hi);
      ASSERT_LT(c.knots[static_cast<std::size_t>(span)], c.knots[static_cast<std::size_t>(span) + 1]);
      ASSERT_LE(c.knots[static_cast<std::size_t>(span)], uc);
      ASSERT_LE(uc, c.knots[static_cast<std::size_t>(span) + 1]);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Basis functions (A2.3)

TEST(NurbsBasis, PartitionOfUnityNonNegativityAndDerivativeRowsSumToZero) {
  std::mt19937 rng(202);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 1 + trial % nurbs::max_degree;
    const int count = p + 1 + std::uniform_int_distribution<int>(0, 20)(rng);
    const Curve c = random_curve(rng, p, count, false, p, uniform(rng, -2, 0), uniform(rng, 0.5, 3));
    for (const double u : probe_parameters(rng, c, 40)) {
      const int span = nurbs::find_span(c, u);
      nurbs::BasisTable N;
      nurbs::basis_derivatives(c, span, u, nurbs::max_order, N);
      double sum = 0.0;
      for (int j = 0; j <= p; ++j) {
        EXPECT_GE(N[0][static_cast<std::size_t>(j)], 0.0) << "degree " << p << ", u = " << u << ", j = " << j;
        EXPECT_LE(N[0][static_cast<std::size_t>(j)], 1.0 + 1e-15);
        sum += N[0][static_cast<std::size_t>(j)];
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << "degree " << p << ", u = " << u;
      for (int k = 1; k <= nurbs::max_order; ++k) {
        double row = 0.0, biggest = 0.0;
        for (int j = 0; j <= p; ++j) {
          row += N[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
          biggest = std::max(biggest, std::abs(N[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)]));
        }
        if (k > p) {
          EXPECT_EQ(biggest, 0.0) << "derivative " << k << " above degree " << p;
        } else {
          EXPECT_LE(std::abs(row), 1e-12 * std::max(biggest, 1.0))
              << "derivative " << k << ", degree " << p << ", u = " << u << ", largest entry " << biggest;
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

TEST(NurbsBasis, AgreesWithTheCoxDeBoorRecursion) {
  std::mt19937 rng(303);
  Worst value, derivative;
  for (int trial = 0; trial < 150; ++trial) {
    const int p = 1 + trial % nurbs::max_degree;
    const int count = p + 1 + std::uniform_int_distribution<int>(0, 15)(rng);
    const Curve c = random_curve(rng, p, count, false, p, uniform(rng, -2, 0), uniform(rng, 0.5, 3));
    const int n = count - 1;
    for (const double u : probe_parameters(rng, c, 30)) {
      const int span = nurbs::find_span(c, u);
      nurbs::BasisTable N;
      nurbs::basis_derivatives(c, span, u, nurbs::max_order, N);
      double ref_sum = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double r = reference::basis(i, p, u, c.knots);
        ref_sum += r;
        const int j = i - (span - p);
        if (j < 0 || j > p) {
          EXPECT_EQ(r, 0.0) << "N_" << i << " outside span " << span << " at u = " << u;
          continue;
        }
        value.add(std::abs(N[0][static_cast<std::size_t>(j)] - r), [&] {
          return "degree " + std::to_string(p) + ", i " + std::to_string(i) + ", u " + std::to_string(u);
        });
        // Derivatives: relative to the size of the k-th derivatives of the whole span.
        for (int k = 1; k <= std::min(p, nurbs::max_order); ++k) {
          double scale = 1.0;
          for (int jj = 0; jj <= p; ++jj)
            scale = std::max(scale, std::abs(N[static_cast<std::size_t>(k)][static_cast<std::size_t>(jj)]));
          const double rk = reference::basis_derivative(i, p, k, u, c.knots);
          derivative.add(std::abs(N[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] - rk) / scale, [&] {
            std::ostringstream s;
            s << "degree " << p << ", i " << i << ", derivative " << k << ", u " << u << ": A2.3 "
              << N[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] << ", reference " << rk;
            return s.str();
          });
        }
      }
      EXPECT_NEAR(ref_sum, 1.0, 1e-13);  // the reference is a partition of unity too
    }
  }
  EXPECT_LE(value.error, 1e-13) << value.where;
  EXPECT_LE(derivative.error, 1e-11) << derivative.where;
}

// ---------------------------------------------------------------------------------------
// Curve derivatives (A4.2)

TEST(NurbsDerivatives, MatchCentralDifferencesOfEvaluate) {
  std::mt19937 rng(404);
  // Central differences with steps h and h/2, Richardson-extrapolated to cancel the
  // O(h^2) truncation error (D = (4 D(h/2) - D(h)) / 3, error O(h^4)). The steps are
  // fractions of the knot span's width w, and the samples lie inside the span so that the
  // widest stencil (u +- 2 h3) stays inside it, where the curve is one smooth (polynomial
  // or rational) piece. The errors are measured relative to the largest difference
  // quotient of that order over the curve.
  const double h1 = 1e-3, h2 = 4e-3, h3 = 1e-2;
  const double at[] = {0.13, 0.29, 0.5, 0.71, 0.87};
  Worst worst[4];
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const bool rational = trial % 2 == 1;
    const int p = 1 + (trial / 2) % 5;
    const Curve c = random_even_curve(rng, p, p + 1 + std::uniform_int_distribution<int>(0, 8)(rng), rational);
    const auto C = [&c](double u) { return nurbs::evaluate(c, u); };
    const auto D1 = [&C](double u, double h) { return (C(u + h) - C(u - h)) / (2 * h); };
    const auto D2 = [&C](double u, double h) { return (C(u + h) - 2.0 * C(u) + C(u - h)) / (h * h); };
    const auto D3 = [&C](double u, double h) {
      return (C(u + 2 * h) - 2.0 * C(u + h) + 2.0 * C(u - h) - C(u - 2 * h)) / (2 * h * h * h);
    };
    const auto richardson = [](const auto& D, double u, double h) { return (4.0 * D(u, h / 2) - D(u, h)) / 3.0; };
    struct Sample {
      double u;
      Point fd[4], exact[4];
    };
    std::vector<Sample> samples;
    double scale[4] = {0, 0, 0, 0};
    for (const auto& [a, b] : spans_of(c)) {
      const double w = b - a;
      for (const double t : at) {
        Sample s;
        s.u = a + t * w;
        const double u = s.u;
        s.fd[1] = richardson(D1, u, h1 * w);
        s.fd[2] = richardson(D2, u, h2 * w);
        s.fd[3] = richardson(D3, u, h3 * w);
        const auto d = nurbs::derivatives(c, u, 3);
        for (int k = 1; k <= 3; ++k) {
          s.exact[k] = d[static_cast<std::size_t>(k)];
          scale[k] = std::max(scale[k], glm::length(s.fd[k]));
        }
        samples.push_back(s);
      }
    }
    for (const auto& s : samples) {
      for (int k = 1; k <= 3; ++k) {
        if (k > p && !rational) {
          EXPECT_EQ(glm::length(s.exact[k]), 0.0) << "derivative " << k << " of a degree " << p << " B-spline";
          continue;
        }
        worst[k].add(glm::length(s.exact[k] - s.fd[k]) / scale[k], [&] {
          return std::string(rational ? "rational" : "non-rational") + " degree " + std::to_string(p) + ", u " +
                 std::to_string(s.u) + ", derivative " + std::to_string(k) + ": A4.2 " + str(s.exact[k]) +
                 ", central difference " + str(s.fd[k]);
        });
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 3000);
  EXPECT_LE(worst[1].error, 1e-7) << worst[1].where;
  EXPECT_LE(worst[2].error, 1e-6) << worst[2].where;
  EXPECT_LE(worst[3].error, 1e-4) << worst[3].where;
}

TEST(NurbsDerivatives, AgreeWithTheReferenceIncludingAtKnots) {
  std::mt19937 rng(505);
  Worst worst[4];
  for (int trial = 0; trial < 120; ++trial) {
    const bool rational = trial % 2 == 1;
    const int p = 1 + (trial / 2) % nurbs::max_degree;
    const Curve c = random_curve(rng, p, p + 1 + std::uniform_int_distribution<int>(0, 12)(rng), rational, p,
                                 uniform(rng, -1, 0), uniform(rng, 0.5, 2));
    // Scales: the largest size of each derivative over the probes.
    const auto us = probe_parameters(rng, c, 40);
    double scale[4] = {magnitude(c.points), 0, 0, 0};
    std::vector<std::array<Point, 4>> refs;
    for (const double u : us) {
      std::array<Point, 4> r;
      for (int k = 0; k <= 3; ++k) {
        r[static_cast<std::size_t>(k)] = reference::derivative(c, u, k);
        if (k > 0) scale[k] = std::max(scale[k], glm::length(r[static_cast<std::size_t>(k)]));
      }
      refs.push_back(r);
    }
    for (std::size_t s = 0; s < us.size(); ++s) {
      const auto d = nurbs::derivatives(c, us[s], 3);
      EXPECT_EQ(glm::length(d[0] - nurbs::evaluate(c, us[s])), 0.0);
      for (int k = 0; k <= 3; ++k) {
        const Point& r = refs[s][static_cast<std::size_t>(k)];
        const Point& got = d[static_cast<std::size_t>(k)];
        if (scale[k] == 0.0) {
          EXPECT_EQ(glm::length(got), 0.0) << "derivative " << k << " of a degree " << p << " curve";
          continue;
        }
        worst[k].add(glm::length(got - r) / scale[k], [&] {
          return std::string(rational ? "rational" : "non-rational") + " degree " + std::to_string(p) + ", u " +
                 std::to_string(us[s]) + ", derivative " + std::to_string(k) + ": got " + str(got) + ", reference " +
                 str(r);
        });
      }
    }
  }
  EXPECT_LE(worst[0].error, 1e-12) << worst[0].where;
  EXPECT_LE(worst[1].error, 1e-10) << worst[1].where;
  EXPECT_LE(worst[2].error, 1e-10) << worst[2].where;
  EXPECT_LE(worst[3].error, 1e-10) << worst[3].where;
}

TEST(NurbsDerivatives, CurvatureAndTorsionFollowTheirFormulas) {
  std::mt19937 rng(606);
  Worst kappa, tau;
  for (int trial = 0; trial < 40; ++trial) {
    const Curve c = random_even_curve(rng, 3 + trial % 3, 8, trial % 2 == 1);
    for (int s = 0; s <= 100; ++s) {
      const double u = s / 100.0;
      const Point d1 = reference::derivative(c, u, 1), d2 = reference::derivative(c, u, 2),
                  d3 = reference::derivative(c, u, 3);
      const Point b = glm::cross(d1, d2);
      const double k = glm::length(b) / std::pow(glm::length(d1), 3.0);
      const double t = glm::dot(b, d3) / glm::dot(b, b);
      kappa.add(std::abs(nurbs::curvature(c, u) - k) / k, [&] { return "u " + std::to_string(u); });
      tau.add(std::abs(nurbs::torsion(c, u) - t) / std::max(std::abs(t), k), [&] { return "u " + std::to_string(u); });
    }
  }
  EXPECT_LE(kappa.error, 1e-9) << kappa.where;
  EXPECT_LE(tau.error, 1e-9) << tau.where;

  // A straight line has no curvature, and a planar curve no torsion.
  const std::vector<Point> line = {Point(0, 0, 0), Point(1, 2, 3), Point(2.5, 5, 7.5), Point(3, 6, 9),
                                   Point(5, 10, 15)};
  const auto li = interpolate(line, Parametrisation::chord_length);
  const std::vector<Point> planar = {Point(0, 0, 1), Point(1, 2, 1), Point(3, -1, 1), Point(4, 4, 1), Point(6, 0, 1)};
  const auto pl = interpolate(planar, Parametrisation::centripetal);
  for (int s = 0; s <= 50; ++s) {
    const double u = s / 50.0;
    EXPECT_LE(nurbs::curvature(li.curve, u), 1e-9) << u;
    EXPECT_LE(std::abs(nurbs::torsion(pl.curve, u)), 1e-9) << u;
  }
}

// ---------------------------------------------------------------------------------------
// A Bezier curve by hand

Point bernstein(const Point P[4], double u) {
  const double v = 1 - u;
  return v * v * v * P[0] + 3 * u * v * v * P[1] + 3 * u * u * v * P[2] + u * u * u * P[3];
}

TEST(NurbsBezier, EvaluateAndDerivativesMatchTheBernsteinForm) {
  const Point P[4] = {Point(0.5, -1, 2), Point(3, 4, -1), Point(-2, 5, 0.25), Point(4, 1, 3)};
  Curve c;
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  c.points.assign(P, P + 4);
  ASSERT_TRUE(nurbs::is_valid(c));
  const double scale = magnitude(c.points);
  for (int s = 0; s <= 256; ++s) {
    const double u = s / 256.0, v = 1 - u;
    const Point d1 = 3.0 * ((P[1] - P[0]) * (v * v) + (P[2] - P[1]) * (2 * u * v) + (P[3] - P[2]) * (u * u));
    const Point d2 = 6.0 * ((P[2] - 2.0 * P[1] + P[0]) * v + (P[3] - 2.0 * P[2] + P[1]) * u);
    const Point d3 = 6.0 * (P[3] - 3.0 * P[2] + 3.0 * P[1] - P[0]);
    const auto d = nurbs::derivatives(c, u, 3);
    EXPECT_LE(glm::length(nurbs::evaluate(c, u) - bernstein(P, u)), 1e-14 * scale) << u;
    EXPECT_LE(glm::length(d[1] - d1), 1e-13 * scale) << u;
    EXPECT_LE(glm::length(d[2] - d2), 1e-13 * scale) << u;
    EXPECT_LE(glm::length(d[3] - d3), 1e-13 * scale) << u;
  }
  // The ends: C(0) = P0, C(1) = P3, C'(0) = 3 (P1 - P0), C'(1) = 3 (P3 - P2).
  EXPECT_EQ(nurbs::evaluate(c, 0.0), P[0]);
  EXPECT_EQ(nurbs::evaluate(c, 1.0), P[3]);
  EXPECT_LE(glm::length(nurbs::derivatives(c, 0.0, 1)[1] - 3.0 * (P[1] - P[0])), 1e-13 * scale);
  EXPECT_LE(glm::length(nurbs::derivatives(c, 1.0, 1)[1] - 3.0 * (P[3] - P[2])), 1e-13 * scale);
}

TEST(NurbsBezier, CurvatureAndTorsionAreZeroWhereTheTangentVanishes) {
  // P1 == P0 makes C'(0) = 3 (P1 - P0) = 0 exactly.
  Curve c;
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  c.points = {Point(1, 2, 3), Point(1, 2, 3), Point(2, 0, 1), Point(4, 1, 0)};
  ASSERT_EQ(nurbs::derivatives(c, 0.0, 1)[1], Point(0.0));
  EXPECT_EQ(nurbs::curvature(c, 0.0), 0.0);
  EXPECT_EQ(nurbs::torsion(c, 0.0), 0.0);
  // A straight Bezier along the x axis: C' x C'' is exactly zero.
  c.points = {Point(0, 0, 0), Point(1, 0, 0), Point(3, 0, 0), Point(4, 0, 0)};
  for (int s = 0; s <= 10; ++s) {
    EXPECT_EQ(nurbs::curvature(c, s / 10.0), 0.0);
    EXPECT_EQ(nurbs::torsion(c, s / 10.0), 0.0);
  }
}

TEST(NurbsBezier, InterpolatingFourPointsGivesTheBezierThroughThem) {
  const std::vector<Point> q = {Point(0, 0, 0), Point(1, 2, 0.5), Point(3, 3, 1), Point(4, 0, 2)};
  for (const auto par : both_parametrisations) {
    SCOPED_TRACE(name(par));
    const auto r = interpolate(q, par);
    ASSERT_EQ(r.curve.degree, 3);
    EXPECT_EQ(r.curve.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
    EXPECT_TRUE(r.curve.weights.empty());
    ASSERT_EQ(r.curve.points.size(), 4u);
    // The parameters by hand.
    double d[3];
    for (int k = 0; k < 3; ++k) {
      d[k] = glm::distance(q[static_cast<std::size_t>(k) + 1], q[static_cast<std::size_t>(k)]);
      if (par == Parametrisation::centripetal) d[k] = std::sqrt(d[k]);
    }
    const double t1 = d[0] / (d[0] + d[1] + d[2]), t2 = (d[0] + d[1]) / (d[0] + d[1] + d[2]);
    ASSERT_EQ(r.parameters.size(), 4u);
    EXPECT_EQ(r.parameters[0], 0.0);
    EXPECT_NEAR(r.parameters[1], t1, 1e-15);
    EXPECT_NEAR(r.parameters[2], t2, 1e-15);
    EXPECT_EQ(r.parameters[3], 1.0);
    // The Bezier through q at 0, t1, t2, 1: P0 = q0, P3 = q3 and, by Cramer's rule,
    // b1(t) P1 + b2(t) P2 = q(t) - b0(t) q0 - b3(t) q3 at t = t1, t2.
    const auto b = [](double t, int i) {
      const double v = 1 - t;
      return i == 0 ? v * v * v : i == 1 ? 3 * t * v * v : i == 2 ? 3 * t * t * v : t * t * t;
    };
    const Point r1 = q[1] - b(t1, 0) * q[0] - b(t1, 3) * q[3];
    const Point r2 = q[2] - b(t2, 0) * q[0] - b(t2, 3) * q[3];
    const double det = b(t1, 1) * b(t2, 2) - b(t1, 2) * b(t2, 1);
    const Point P[4] = {q[0], (r1 * b(t2, 2) - r2 * b(t1, 2)) / det, (r2 * b(t1, 1) - r1 * b(t2, 1)) / det, q[3]};
    const double scale = magnitude(q);
    for (int i = 0; i < 4; ++i)
      EXPECT_LE(glm::distance(r.curve.points[static_cast<std::size_t>(i)], P[i]), 1e-12 * scale)
          << "control point " << i << ": got " << str(r.curve.points[static_cast<std::size_t>(i)]) << ", expected "
          << str(P[i]);
    for (int s = 0; s <= 100; ++s) {
      const double u = s / 100.0;
      EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, u), bernstein(P, u)), 1e-12 * scale) << u;
    }
  }
}

TEST(NurbsBezier, TwoAndThreePointsGiveASegmentAndAParabola) {
  const Point a(1, 2, 3), b(4, -2, 3), m(2, 2, 0);
  const auto seg = interpolate({a, b}, Parametrisation::chord_length);
  EXPECT_EQ(seg.curve.degree, 1);
  EXPECT_EQ(seg.curve.knots, (std::vector<double>{0, 0, 1, 1}));
  for (int s = 0; s <= 20; ++s) {
    const double u = s / 20.0;
    EXPECT_LE(glm::distance(nurbs::evaluate(seg.curve, u), (1 - u) * a + u * b), 1e-14 * 5) << u;
  }
  EXPECT_NEAR(nurbs::arc_length(seg.curve, 0, 1), 5.0, 1e-12);

  const auto par = interpolate({a, m, b}, Parametrisation::chord_length);
  EXPECT_EQ(par.curve.degree, 2);
  EXPECT_EQ(par.curve.knots, (std::vector<double>{0, 0, 0, 1, 1, 1}));
  const double t = glm::distance(a, m) / (glm::distance(a, m) + glm::distance(m, b));
  const Point P1 = (m - (1 - t) * (1 - t) * a - t * t * b) / (2 * t * (1 - t));
  for (int s = 0; s <= 20; ++s) {
    const double u = s / 20.0;
    const Point expected = (1 - u) * (1 - u) * a + 2 * u * (1 - u) * P1 + u * u * b;
    EXPECT_LE(glm::distance(nurbs::evaluate(par.curve, u), expected), 1e-13 * 5) << u;
  }
}

// ---------------------------------------------------------------------------------------
// Rational curves: circles

Curve quarter_circle() {
  Curve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.points = {Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  c.weights = {1, std::numbers::sqrt2 / 2, 1};
  return c;
}

TEST(NurbsRational, QuarterCircleLiesOnTheUnitCircleWithUnitCurvature) {
  const Curve c = quarter_circle();
  ASSERT_TRUE(nurbs::is_valid(c));
  for (int s = 0; s <= 200; ++s) {
    const double u = s / 200.0;
    const Point p = nurbs::evaluate(c, u);
    EXPECT_NEAR(glm::length(p), 1.0, 1e-14) << u;
    EXPECT_EQ(p.z, 0.0);
    EXPECT_GE(p.x, -1e-15);
    EXPECT_GE(p.y, -1e-15);
    EXPECT_LE(glm::distance(p, reference::point(c, u)), 1e-14) << u;
    // The tangent is perpendicular to the radius.
    const Point d1 = nurbs::derivatives(c, u, 1)[1];
    EXPECT_NEAR(glm::dot(p, d1) / glm::length(d1), 0.0, 1e-13) << u;
    EXPECT_NEAR(nurbs::curvature(c, u), 1.0, 1e-9) << u;
    EXPECT_NEAR(nurbs::torsion(c, u), 0.0, 1e-9) << u;
    // Arc length from the start is the polar angle.
    EXPECT_NEAR(nurbs::arc_length(c, 0.0, u), std::atan2(p.y, p.x), 1e-9) << u;
  }
  EXPECT_EQ(nurbs::evaluate(c, 0.0), Point(1, 0, 0));
  EXPECT_EQ(nurbs::evaluate(c, 1.0), Point(0, 1, 0));
  EXPECT_NEAR(nurbs::evaluate(c, 0.5).x, std::numbers::sqrt2 / 2, 1e-15);
  EXPECT_NEAR(nurbs::arc_length(c, 0.0, 1.0), std::numbers::pi / 2, 1e-9);
}

TEST(NurbsRational, QuarterCircleDerivativesMatchCentralDifferences) {
  const Curve c = quarter_circle();
  const auto C = [&c](double u) { return nurbs::evaluate(c, u); };
  for (int s = 1; s < 50; ++s) {
    const double u = s / 50.0;
    const auto d = nurbs::derivatives(c, u, 3);
    double h = 1e-5;
    const Point fd1 = (C(u + h) - C(u - h)) / (2 * h);
    h = 1e-3;
    const Point fd2 = (C(u + h) - 2.0 * C(u) + C(u - h)) / (h * h);
    h = 5e-3;
    const Point fd3 = (C(u + 2 * h) - 2.0 * C(u + h) + 2.0 * C(u - h) - C(u - 2 * h)) / (2 * h * h * h);
    // |C'| ~ 1.4, |C''| ~ 2.8, |C'''| ~ 8 on this curve.
    EXPECT_LE(glm::length(d[1] - fd1), 1e-8) << u << ": " << str(d[1]) << " vs " << str(fd1);
    EXPECT_LE(glm::length(d[2] - fd2), 1e-5) << u << ": " << str(d[2]) << " vs " << str(fd2);
    EXPECT_LE(glm::length(d[3] - fd3), 1e-3) << u << ": " << str(d[3]) << " vs " << str(fd3);
  }
}

TEST(NurbsRational, TiltedFullCircleWithDoubleKnots) {
  const double R = 2.5, w = std::numbers::sqrt2 / 2;
  const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, -2, 0.5))));
  const Point centre(3, -1, 2);
  Curve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  const Point square[9] = {Point(1, 0, 0),  Point(1, 1, 0),   Point(0, 1, 0),  Point(-1, 1, 0), Point(-1, 0, 0),
                           Point(-1, -1, 0), Point(0, -1, 0), Point(1, -1, 0), Point(1, 0, 0)};
  for (int i = 0; i < 9; ++i) {
    c.points.push_back(centre + rot * (R * square[i]));
    c.weights.push_back(i % 2 == 0 ? 1.0 : w);
  }
  ASSERT_TRUE(nurbs::is_valid(c));
  for (int s = 0; s <= 400; ++s) {
    const double u = s / 400.0;  // includes the double knots
    EXPECT_NEAR(glm::distance(nurbs::evaluate(c, u), centre), R, 1e-13) << u;
    EXPECT_NEAR(nurbs::curvature(c, u), 1 / R, 1e-9) << u;
    EXPECT_NEAR(nurbs::torsion(c, u), 0.0, 1e-9) << u;
  }
  EXPECT_NEAR(nurbs::arc_length(c, 0.0, 1.0), 2 * std::numbers::pi * R, 1e-9 * 2 * std::numbers::pi * R);
  EXPECT_NEAR(nurbs::arc_length(c, 0.25, 0.75), std::numbers::pi * R, 1e-9 * std::numbers::pi * R);
  EXPECT_NEAR(nurbs::arc_length(c, 0.125, 0.375), std::numbers::pi * R / 2, 1e-9 * std::numbers::pi * R);
}

// ---------------------------------------------------------------------------------------
// Curvature and torsion of a helix; arc length

TEST(NurbsMeasure, InterpolatedHelixHasTheHelixCurvatureAndTorsion) {
  // A helix of radius r rising c per radian: curvature r / (r^2 + c^2), torsion
  // c / (r^2 + c^2). Interpolated with points every dt radians, the cubic spline's
  // second derivative is off by about dt^2 / 12 relative (h^2 f'''' / 12, and
  // f'''' = -f'' for cos and sin) and its third by about dt^2 / 6, so curvature and
  // torsion must converge at second order: within dt^2 / 8 and dt^2 / 4, and four
  // times closer when dt halves.
  const double r = 2.0, c = 0.5;
  const double kappa = r / (r * r + c * c), tau = c / (r * r + c * c);
  const int turns = 3;
  const double turn = 2 * std::numbers::pi * turns;
  const double length = turn * std::sqrt(r * r + c * c);
  for (const auto par : both_parametrisations) {
    SCOPED_TRACE(name(par));
    double previous_k = 0.0, previous_t = 0.0;
    for (const int per_turn : {40, 80, 160}) {
      SCOPED_TRACE(std::to_string(per_turn) + " points per turn");
      const int count = per_turn * turns + 1;
      std::vector<Point> q;
      for (int k = 0; k < count; ++k) {
        const double t = turn * k / (count - 1);
        q.push_back(Point(r * std::cos(t), r * std::sin(t), c * t));
      }
      const auto h = interpolate(q, par);
      double worst_k = 0.0, worst_t = 0.0;
      for (int s = 0; s <= 1000; ++s) {
        const double u = 0.3 + 0.4 * s / 1000.0;  // the middle, away from the free ends
        worst_k = std::max(worst_k, std::abs(nurbs::curvature(h.curve, u) - kappa) / kappa);
        worst_t = std::max(worst_t, std::abs(nurbs::torsion(h.curve, u) - tau) / tau);
      }
      const double dt = 2 * std::numbers::pi / per_turn;
      EXPECT_LE(worst_k, dt * dt / 8);
      EXPECT_LE(worst_t, dt * dt / 4);
      if (previous_k > 0.0) {
        EXPECT_NEAR(previous_k / worst_k, 4.0, 0.5);
        EXPECT_NEAR(previous_t / worst_t, 4.0, 0.5);
      }
      previous_k = worst_k;
      previous_t = worst_t;
      if (per_turn >= 80) {
        EXPECT_NEAR(nurbs::arc_length(h.curve, 0, 1), length, 1e-6 * length);
      }
    }
  }
}

TEST(NurbsMeasure, ArcLengthOfAStraightInterpolantIsTheDistance) {
  std::mt19937 rng(707);
  for (int trial = 0; trial < 40; ++trial) {
    const Point a = random_cloud(rng, 1, 10.0)[0];
    const Point dir = glm::normalize(random_cloud(rng, 1)[0]);
    const int count = 2 + trial;
    std::vector<Point> q{a};
    for (int k = 1; k < count; ++k) q.push_back(q.back() + uniform(rng, 0.1, 2.0) * dir);
    const double L = glm::distance(q.front(), q.back());
    // Chord-length parameters make the interpolant the line at constant speed: splines
    // reproduce linear functions.
    const auto c = interpolate(q, Parametrisation::chord_length);
    EXPECT_NEAR(nurbs::arc_length(c.curve, 0, 1), L, 1e-9 * L) << count << " points";
    for (int s = 0; s <= 10; ++s) {
      const double u = s / 10.0;
      EXPECT_NEAR(nurbs::arc_length(c.curve, 0, u), u * L, 1e-9 * L) << count << " points, u " << u;
      EXPECT_LE(glm::distance(nurbs::evaluate(c.curve, u), a + (u * L) * dir), 1e-9 * magnitude(q));
    }
    // Equally spaced points: both parametrisations agree and give the same line.
    std::vector<Point> even;
    for (int k = 0; k < count; ++k) even.push_back(a + (0.75 * k) * dir);
    const double Le = 0.75 * (count - 1);
    for (const auto par : both_parametrisations)
      EXPECT_NEAR(nurbs::arc_length(interpolate(even, par).curve, 0, 1), Le, 1e-9 * Le) << name(par);
  }
}

TEST(NurbsMeasure, ArcLengthIsAdditiveAndMatchesAFinePolyline) {
  std::mt19937 rng(808);
  for (int trial = 0; trial < 30; ++trial) {
    const auto q = random_walk(rng, 3 + trial);
    const auto c = interpolate(q, both_parametrisations[trial % 2]).curve;
    const double total = nurbs::arc_length(c, 0, 1);
    // At least the length of the data polygon.
    double polygon = 0.0;
    for (std::size_t k = 1; k < q.size(); ++k) polygon += glm::distance(q[k], q[k - 1]);
    EXPECT_GE(total, polygon * (1 - 1e-12));
    for (int s = 0; s < 20; ++s) {
      double u[3] = {uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)};
      if (s == 0) u[1] = c.knots[c.knots.size() / 2];  // a split at a knot
      std::sort(u, u + 3);
      const double ab = nurbs::arc_length(c, u[0], u[1]), bc = nurbs::arc_length(c, u[1], u[2]),
                   ac = nurbs::arc_length(c, u[0], u[2]);
      EXPECT_NEAR(ab + bc, ac, 1e-9 * ac) << "u = " << u[0] << ", " << u[1] << ", " << u[2];
    }
    EXPECT_NEAR(nurbs::arc_length(c, 0, 0.5) + nurbs::arc_length(c, 0.5, 1), total, 1e-9 * total);
    EXPECT_EQ(nurbs::arc_length(c, 0.4, 0.4), 0.0);
    // Against inscribed polylines through the reference curve, with M and 2M segments,
    // Richardson-extrapolated: the polyline error is c / M^2 + O(1 / M^3).
    const auto ref = reference::interpolate(q, trial % 2 == 1);
    const auto polyline = [&ref](int M) {
      double len = 0.0;
      Point prev = reference::point(ref, 0.0);
      for (int i = 1; i <= M; ++i) {
        const Point next = reference::point(ref, static_cast<double>(i) / M);
        len += glm::distance(prev, next);
        prev = next;
      }
      return len;
    };
    const int M = 2000;
    const double coarse = polyline(M), fine = polyline(2 * M);
    EXPECT_LT(coarse, fine);
    EXPECT_LE(fine, total * (1 + 1e-12));
    EXPECT_NEAR((4 * fine - coarse) / 3, total, 1e-7 * total) << q.size() << " points";
  }
}

// ---------------------------------------------------------------------------------------
// Interpolation

TEST(NurbsInterpolate, PassesThroughEveryDataPoint) {
  std::mt19937 rng(909);
  Worst worst;
  for (int size = 2; size <= 200; ++size) {
    for (int family = 0; family < 2; ++family) {
      const auto q = family == 0 ? random_cloud(rng, size, uniform(rng, 0.01, 100.0)) : random_walk(rng, size);
      const double scale = magnitude(q);
      for (const auto par : both_parametrisations) {
        const auto r = interpolate(q, par);
        ASSERT_TRUE(nurbs::is_valid(r.curve)) << size << " points, " << name(par);
        ASSERT_EQ(r.curve.degree, std::min(3, size - 1));
        ASSERT_EQ(r.curve.points.size(), q.size());
        ASSERT_TRUE(r.curve.weights.empty());
        ASSERT_EQ(r.parameters.size(), q.size());
        EXPECT_EQ(r.parameters.front(), 0.0);
        EXPECT_EQ(r.parameters.back(), 1.0);
        EXPECT_EQ(r.curve.knots.front(), 0.0);
        EXPECT_EQ(r.curve.knots.back(), 1.0);
        for (std::size_t k = 0; k < q.size(); ++k) {
          if (k > 0) {
            EXPECT_LT(r.parameters[k - 1], r.parameters[k]);
          }
          const Point p = nurbs::evaluate(r.curve, r.parameters[k]);
          worst.add(glm::distance(p, q[k]) / scale, [&] {
            return std::to_string(size) + " points (" + (family == 0 ? "cloud" : "walk") + ", " + name(par) +
                   "), point " + std::to_string(k) + ": " + str(q[k]) + ", curve " + str(p);
          });
        }
      }
    }
  }
  EXPECT_LE(worst.error, 1e-9) << worst.where;
}

TEST(NurbsInterpolate, AgreesWithTheDenseReference) {
  std::mt19937 rng(1010);
  Worst knots, params, control, points, points_curve;
  for (const int size : {2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 15, 17, 20, 25, 33, 40, 50, 64, 77, 100, 128, 150, 200}) {
    for (int family = 0; family < 2; ++family) {
      const auto q = family == 0 ? random_cloud(rng, size, 5.0, Point(1, -2, 3)) : random_walk(rng, size);
      for (const auto par : both_parametrisations) {
        const auto where = [&] {
          return std::to_string(size) + " points (" + (family == 0 ? "cloud" : "walk") + ", " + name(par) + ")";
        };
        const auto r = interpolate(q, par);
        const auto ref = reference::interpolate(q, par == Parametrisation::centripetal);
        ASSERT_EQ(r.curve.degree, ref.degree) << where();
        ASSERT_EQ(r.curve.knots.size(), ref.knots.size()) << where();
        ASSERT_EQ(r.curve.points.size(), ref.control.size()) << where();
        ASSERT_EQ(r.parameters.size(), ref.params.size()) << where();
        for (std::size_t i = 0; i < ref.knots.size(); ++i)
          knots.add(std::abs(r.curve.knots[i] - ref.knots[i]), [&] { return where() + ", knot " + std::to_string(i); });
        for (std::size_t i = 0; i < ref.params.size(); ++i)
          params.add(std::abs(r.parameters[i] - ref.params[i]),
                     [&] { return where() + ", parameter " + std::to_string(i); });
        const double cscale = magnitude(ref.control);
        for (std::size_t i = 0; i < ref.control.size(); ++i)
          control.add(glm::distance(r.curve.points[i], ref.control[i]) / cscale, [&] {
            return where() + ", control point " + std::to_string(i) + ": " + str(r.curve.points[i]) + " vs " +
                   str(ref.control[i]);
          });
        const double scale = magnitude(q);
        for (int s = 0; s <= 300; ++s) {
          const double u = s / 300.0;
          const Point p = nurbs::evaluate(r.curve, u);
          points.add(glm::distance(p, reference::point(ref, u)) / scale,
                     [&] { return where() + ", u " + std::to_string(u); });
          // The reference evaluator on the project's own curve as well.
          points_curve.add(glm::distance(p, reference::point(r.curve, u)) / scale,
                           [&] { return where() + ", u " + std::to_string(u); });
        }
      }
    }
  }
  EXPECT_LE(knots.error, 1e-14) << knots.where;
  EXPECT_LE(params.error, 1e-14) << params.where;
  EXPECT_LE(control.error, 1e-9) << control.where;
  EXPECT_LE(points.error, 1e-9) << points.where;
  EXPECT_LE(points_curve.error, 1e-12) << points_curve.where;
}

TEST(NurbsInterpolate, VeryUnevenSpacing) {
  // Chords spread log-uniformly over 1e-4..1 (and 1e-8..1): the banded solve without
  // pivoting must still pass through the points and, at 1e-4, give the reference's
  // control points. (At 1e-8 the control points themselves are ill-conditioned, so only
  // the residual is checked there.)
  std::mt19937 rng(1414);
  for (const double spread : {1e-4, 1e-8}) {
    for (const int size : {4, 5, 10, 30, 100}) {
      for (const auto par : both_parametrisations) {
        std::vector<Point> q{Point(0.0)};
        Point dir(1, 0, 0);
        while (static_cast<int>(q.size()) < size) {
          dir = glm::normalize(dir + 1.2 * random_cloud(rng, 1)[0]);
          q.push_back(q.back() + std::exp(uniform(rng, std::log(spread), 0.0)) * dir);
        }
        const std::string where = std::to_string(size) + " points, spread " + std::to_string(spread) + ", " + name(par);
        const auto r = interpolate(q, par);
        const double scale = magnitude(q);
        for (std::size_t k = 0; k < q.size(); ++k)
          EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, r.parameters[k]), q[k]), 1e-9 * scale) << where << ", " << k;
        if (spread < 1e-4) continue;
        const auto ref = reference::interpolate(q, par == Parametrisation::centripetal);
        const double cscale = magnitude(ref.control);
        for (std::size_t i = 0; i < q.size(); ++i)
          EXPECT_LE(glm::distance(r.curve.points[i], ref.control[i]), 1e-9 * cscale)
              << where << ", control point " << i;
      }
    }
  }
}

TEST(NurbsInterpolate, InvariantUnderTranslationRotationAndUniformScaling) {
  std::mt19937 rng(1111);
  struct Similarity {
    std::string what;
    glm::dmat3 linear;
    Point shift;
  };
  const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), 1.234, glm::normalize(glm::dvec3(0.3, -0.8, 0.52))));
  const glm::dmat3 rot2(glm::rotate(glm::dmat4(1.0), -2.9, glm::dvec3(0, 0, 1)));
  const std::vector<Similarity> transforms = {
      {"translation", glm::dmat3(1.0), Point(10.0, -3.5, 7.25)},
      {"rotation", rot, Point(0.0)},
      {"rotation about z", rot2, Point(0.0)},
      {"scaling by 3.7", glm::dmat3(3.7), Point(0.0)},
      {"scaling by 1e-3", glm::dmat3(1e-3), Point(0.0)},
      {"scaling by 250", glm::dmat3(250.0), Point(0.0)},
      {"all three", 0.42 * rot, Point(-4.0, 2.0, 1.0)},
  };
  for (const auto& T : transforms) {
    SCOPED_TRACE(T.what);
    const auto apply = [&T](const Point& p) { return T.linear * p + T.shift; };
    Worst worst, control;
    for (const int size : {2, 3, 4, 5, 8, 13, 30, 75, 200}) {
      const auto q = random_walk(rng, size);
      std::vector<Point> tq;
      for (const auto& p : q) tq.push_back(apply(p));
      const double scale = magnitude(tq);
      for (const auto par : both_parametrisations) {
        const auto a = interpolate(q, par), b = interpolate(tq, par);
        for (std::size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(a.parameters[k], b.parameters[k], 1e-13);
        EXPECT_EQ(a.curve.knots.size(), b.curve.knots.size());
        for (std::size_t i = 0; i < a.curve.points.size(); ++i)
          control.add(glm::distance(apply(a.curve.points[i]), b.curve.points[i]) / scale,
                      [&] { return std::to_string(size) + " points, control point " + std::to_string(i); });
        for (int s = 0; s <= 500; ++s) {
          const double u = s / 500.0;
          worst.add(glm::distance(apply(nurbs::evaluate(a.curve, u)), nurbs::evaluate(b.curve, u)) / scale, [&] {
            return std::to_string(size) + " points, " + name(par) + ", u " + std::to_string(u);
          });
        }
      }
    }
    EXPECT_LE(worst.error, 1e-9) << worst.where;
    EXPECT_LE(control.error, 1e-9) << control.where;
  }
}

TEST(NurbsInterpolate, EndDerivativesArePassedThroughAndMet) {
  std::mt19937 rng(1212);
  Worst through, ends, vs_ref;
  for (int size = 2; size <= 60; ++size) {
    const auto q = random_walk(rng, size);
    double L = 0.0;
    for (std::size_t k = 1; k < q.size(); ++k) L += glm::distance(q[k], q[k - 1]);
    const double scale = magnitude(q);
    for (const auto par : both_parametrisations) {
      InterpolationOptions o;
      o.parametrisation = par;
      // Tangent directions times the length, as the header asks, plus a random stretch.
      const Point d0 = uniform(rng, 0.5, 2.0) * L * glm::normalize(random_cloud(rng, 1)[0]);
      const Point d1 = uniform(rng, 0.5, 2.0) * L * glm::normalize(random_cloud(rng, 1)[0]);
      o.start_derivative = d0;
      o.end_derivative = d1;
      const auto r = nurbs::interpolate(q, o);
      const auto where = [&] { return std::to_string(size) + " points, " + name(par); };
      ASSERT_TRUE(nurbs::is_valid(r.curve)) << where();
      ASSERT_EQ(r.curve.degree, 3) << where();
      ASSERT_EQ(r.curve.points.size(), q.size() + 2) << where();
      ASSERT_EQ(r.parameters.size(), q.size()) << where();
      // C(0) = Q0 and C(1) = Qn, and the two derivatives.
      EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, 0.0), q.front()), 1e-14 * scale) << where();
      EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, 1.0), q.back()), 1e-12 * scale) << where();
      const double dscale = std::max(glm::length(d0), glm::length(d1));
      ends.add(glm::distance(nurbs::derivatives(r.curve, 0.0, 1)[1], d0) / dscale, [&] { return where() + ", C'(0)"; });
      ends.add(glm::distance(nurbs::derivatives(r.curve, 1.0, 1)[1], d1) / dscale, [&] { return where() + ", C'(1)"; });
      for (std::size_t k = 0; k < q.size(); ++k)
        through.add(glm::distance(nurbs::evaluate(r.curve, r.parameters[k]), q[k]) / scale,
                    [&] { return where() + ", point " + std::to_string(k); });
      // The same curve as the dense reference with end derivative rows.
      const auto ref = reference::interpolate_with_end_derivatives(q, par == Parametrisation::centripetal, d0, d1);
      ASSERT_EQ(r.curve.knots.size(), ref.knots.size()) << where();
      for (std::size_t i = 0; i < ref.knots.size(); ++i)
        EXPECT_NEAR(r.curve.knots[i], ref.knots[i], 1e-14) << where() << ", knot " << i;
      for (int s = 0; s <= 100; ++s) {
        const double u = s / 100.0;
        vs_ref.add(glm::distance(nurbs::evaluate(r.curve, u), reference::point(ref, u)) / scale,
                   [&] { return where() + ", u " + std::to_string(u); });
      }
    }
  }
  EXPECT_LE(through.error, 1e-9) << through.where;
  EXPECT_LE(ends.error, 1e-9) << ends.where;
  EXPECT_LE(vs_ref.error, 1e-9) << vs_ref.where;
}

TEST(NurbsInterpolate, EndDerivativesOfTwoPointsGiveTheHermiteCubic) {
  const Point a(0, 0, 0), b(2, 1, 0), d0(3, 0, 1), d1(0, 3, -1);
  InterpolationOptions o;
  o.start_derivative = d0;
  o.end_derivative = d1;
  const auto r = nurbs::interpolate(std::vector<Point>{a, b}, o);
  ASSERT_EQ(r.curve.points.size(), 4u);
  EXPECT_EQ(r.curve.knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  // Hermite: the Bezier with P1 = a + d0 / 3 and P2 = b - d1 / 3.
  const Point P[4] = {a, a + d0 / 3.0, b - d1 / 3.0, b};
  for (int i = 0; i < 4; ++i) EXPECT_LE(glm::distance(r.curve.points[static_cast<std::size_t>(i)], P[i]), 1e-14) << i;
  for (int s = 0; s <= 20; ++s)
    EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, s / 20.0), bernstein(P, s / 20.0)), 1e-14) << s;
}

TEST(NurbsInterpolate, RejectsTooFewPointsAndConsecutiveDuplicates) {
  const Point a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 1);
  InterpolationOptions with_ends;
  with_ends.start_derivative = Point(1, 0, 0);
  with_ends.end_derivative = Point(0, 1, 0);
  for (const auto par : both_parametrisations) {
    SCOPED_TRACE(name(par));
    InterpolationOptions o;
    o.parametrisation = par;
    with_ends.parametrisation = par;
    for (const auto& bad : std::vector<std::vector<Point>>{
             {}, {a}, {a, a}, {a, a, b}, {a, b, b, c}, {a, b, c, c}, {a, b, c, d, d}, {a, b, c, c, d, a}}) {
      EXPECT_THROW(nurbs::interpolate(bad, o), std::invalid_argument) << bad.size() << " points";
      EXPECT_THROW(nurbs::interpolate(bad, with_ends), std::invalid_argument) << bad.size() << " points";
      if (bad.size() >= 2) {
        EXPECT_THROW(reference::interpolate(bad, par == Parametrisation::centripetal), std::invalid_argument);
      }
    }
    // Equal points that are not consecutive are fine: a closed polygon.
    const std::vector<Point> closed = {a, b, c, d, a};
    const auto r = nurbs::interpolate(closed, o);
    EXPECT_TRUE(nurbs::is_valid(r.curve));
    for (std::size_t k = 0; k < closed.size(); ++k)
      EXPECT_LE(glm::distance(nurbs::evaluate(r.curve, r.parameters[k]), closed[k]), 1e-12);
  }
}

TEST(NurbsIsValid, AcceptsInterpolantsAndGoodCurvesAndRejectsBrokenOnes) {
  std::mt19937 rng(1313);
  for (int size = 2; size <= 40; ++size)
    for (const auto par : both_parametrisations)
      EXPECT_TRUE(nurbs::is_valid(interpolate(random_walk(rng, size), par).curve)) << size << " points";
  EXPECT_TRUE(nurbs::is_valid(quarter_circle()));
  for (int p = 1; p <= nurbs::max_degree; ++p)
    EXPECT_TRUE(nurbs::is_valid(random_curve(rng, p, p + 6, true, p, -3.0, -1.0))) << p;

  const Curve good = interpolate(random_walk(rng, 9), Parametrisation::chord_length).curve;
  ASSERT_TRUE(nurbs::is_valid(good));
  const auto broken = [&good](const std::string& what, const std::function<void(Curve&)>& change) {
    Curve c = good;
    change(c);
    EXPECT_FALSE(nurbs::is_valid(c)) << what;
  };
  broken("degree 0", [](Curve& c) { c.degree = 0; });
  broken("negative degree", [](Curve& c) { c.degree = -1; });
  broken("degree raised without more knots", [](Curve& c) { c.degree = 4; });
  broken("a knot missing", [](Curve& c) { c.knots.pop_back(); });
  broken("a knot too many", [](Curve& c) { c.knots.push_back(1.0); });
  broken("a control point missing", [](Curve& c) { c.points.pop_back(); });
  broken("no control points", [](Curve& c) { c.points.clear(); });
  broken("decreasing knots", [](Curve& c) { std::swap(c.knots[5], c.knots[6]); c.knots[5] += 0.01; });
  broken("start not clamped", [](Curve& c) { c.knots[3] = 0.5 * c.knots[4]; });
  broken("end not clamped", [](Curve& c) {
    const std::size_t m = c.knots.size() - 1;
    c.knots[m - 3] = 0.5 * (c.knots[m - 4] + 1.0);
  });
  broken("empty domain", [](Curve& c) { std::fill(c.knots.begin(), c.knots.end(), 0.5); });
  broken("too few weights", [](Curve& c) { c.weights.assign(c.points.size() - 1, 1.0); });
  broken("too many weights", [](Curve& c) { c.weights.assign(c.points.size() + 1, 1.0); });
  broken("a zero weight", [](Curve& c) { c.weights.assign(c.points.size(), 1.0); c.weights[4] = 0.0; });
  broken("a negative weight", [](Curve& c) { c.weights.assign(c.points.size(), 1.0); c.weights[0] = -0.5; });
  // Too few control points for the degree, with a knot vector of the matching length.
  Curve few;
  few.degree = 3;
  few.points.assign(3, Point(0.0));
  few.knots = {0, 0, 0, 0, 1, 1, 1};
  EXPECT_FALSE(nurbs::is_valid(few));
  // And one that is fine: all weights given and positive.
  Curve weighted = good;
  weighted.weights.assign(good.points.size(), 2.0);
  EXPECT_TRUE(nurbs::is_valid(weighted));
  // Equal weights do not change the curve.
  for (int s = 0; s <= 20; ++s)
    EXPECT_LE(glm::distance(nurbs::evaluate(weighted, s / 20.0), nurbs::evaluate(good, s / 20.0)), 1e-12);
}

}  // namespace
}  // namespace knitc
