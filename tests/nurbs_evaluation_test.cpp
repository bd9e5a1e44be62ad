// The NURBS core's evaluation: find_span, the basis functions and their derivatives
// (partition of unity, non-negativity, derivative rows summing to zero, agreement with the
// Cox-de Boor recursion), curve derivatives against central differences and against
// reference_nurbs.hpp, a Bezier curve checked by hand, and rational circles (on the circle,
// curvature, torsion, arc length). Random data comes from std::mt19937 with fixed seeds.
#include "nurbs_support.hpp"

namespace knitc {
namespace {

using namespace nurbs_test;

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

TEST(NurbsFindSpan, WalkingUpFromAnySpanFindsTheSameSpan) {
  // next_span from every span, for every parameter (some far past it, some behind it,
  // some at the knots and the ends): find_span's answer each time.
  std::mt19937 rng(102);
  for (int trial = 0; trial < 100; ++trial) {
    const int p = 1 + trial % 4;
    const int count = p + 1 + std::uniform_int_distribution<int>(0, 60)(rng);
    const double lo = uniform(rng, -3, 1), hi = lo + uniform(rng, 0.5, 4);
    const Curve c = random_curve(rng, p, count, false, p, lo, hi);
    ASSERT_TRUE(nurbs::is_valid(c));
    auto us = probe_parameters(rng, c, 40);
    us.insert(us.end(), c.knots.begin(), c.knots.end());
    us.push_back(lo - 1.0);
    us.push_back(hi + 1.0);
    std::sort(us.begin(), us.end());
    for (int from = 0; from < static_cast<int>(c.knots.size()); ++from)
      for (const double u : us)
        ASSERT_EQ(nurbs::next_span(c, from, u), nurbs::find_span(c, u)) << "degree " << p << ", from " << from << ", u = " << u;
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
// A span made ready once (nurbs::Span): the cubic's power form, anything else by A4.2

TEST(NurbsSpan, AgreesWithTheDerivativesInEverySpanOfEveryKind) {
  std::mt19937 rng(808);
  int power = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const bool rational = trial % 4 == 3;
    const int p = trial % 4 == 2 ? 2 : 3;
    const Curve c = random_even_curve(rng, p, p + 1 + std::uniform_int_distribution<int>(0, 9)(rng), rational);
    double scale[4] = {0, 0, 0, 0};
    for (const auto& [a, b] : spans_of(c))
      for (int k = 0; k <= 3; ++k) scale[k] = std::max(scale[k], glm::length(nurbs::derivatives(c, a, 3)[static_cast<std::size_t>(k)]));
    for (const auto& [a, b] : spans_of(c)) {
      const nurbs::Span span(c, nurbs::find_span(c, a));
      EXPECT_TRUE(span.holds(a));
      EXPECT_FALSE(span.holds(b));
      power += p == 3 && !rational;
      // Both ends of the span and inside it: the span's polynomial holds on its closed interval.
      for (const double t : {0.0, 0.07, 0.5, 0.93, 1.0}) {
        const double u = a + t * (b - a);
        const auto want = nurbs::derivatives(c, span.index(), u, 3);
        const auto got = span.derivatives(u, 3);
        for (int k = 0; k <= 3; ++k)
          EXPECT_LE(glm::length(got[static_cast<std::size_t>(k)] - want[static_cast<std::size_t>(k)]), 1e-12 * std::max(1.0, scale[k]))
              << "degree " << p << (rational ? " rational" : "") << ", u " << u << ", derivative " << k;
        EXPECT_NEAR(span.speed(u), glm::length(want[1]), 1e-12 * std::max(1.0, scale[1]));
        EXPECT_NEAR(span.curvature(u), nurbs::curvature(c, span.index(), u), 1e-9 * std::max(1.0, nurbs::curvature(c, span.index(), u)));
      }
    }
  }
  EXPECT_GT(power, 100);  // the power form itself was checked, not only the fallback
}

TEST(NurbsMeasure, SegmentLengthsAreEachStepsSegmentLength) {
  std::mt19937 rng(909);
  const Curve c = random_even_curve(rng, 3, 12, false);
  // Steps within one span, across one knot, across several, and of zero length.
  std::vector<double> u = {0.0, 0.01, 0.02, 0.02, 0.3, 0.31, 0.8, 0.95, 1.0};
  std::vector<double> lengths(u.size() - 1);
  nurbs::segment_lengths(c, u, lengths);
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    EXPECT_NEAR(lengths[i], nurbs::segment_length(c, u[i], u[i + 1]), 1e-13) << i;
    // (One rule a knot span: close to the adaptive length on the short steps sampling makes.)
    if (u[i + 1] - u[i] <= 0.02) {
      EXPECT_NEAR(lengths[i], nurbs::arc_length(c, u[i], u[i + 1]), 1e-9) << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Rational curves: circles

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

}  // namespace
}  // namespace knitc
