// The NURBS core's measures: curvature and torsion of an interpolated helix, arc length
// of lines and its additivity against a fine polyline. Random data comes from
// std::mt19937 with fixed seeds, so every run is the same.
#include "nurbs_support.hpp"

namespace knitc {
namespace {

using namespace nurbs_test;

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

}  // namespace
}  // namespace knitc
