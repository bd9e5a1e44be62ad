// The NURBS core's interpolation: through every data point, invariant under similarity
// transforms, with end derivatives, equal to the independent dense implementation in
// reference_nurbs.hpp, the same on any number of threads, and rejecting bad input.
// Random data comes from std::mt19937 with fixed seeds, so every run is the same.
#include "nurbs_support.hpp"

namespace knitc {
namespace {

using namespace nurbs_test;

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

// On `threads`, with end derivatives (+x at the start, +y at the end) or without.
InterpolationOptions with_ends(bool ends, int threads) {
  InterpolationOptions o;
  if (ends) {
    o.start_derivative = Point(1.0, 0.0, 0.0);
    o.end_derivative = Point(0.0, 1.0, 0.0);
  }
  o.threads = threads;
  return o;
}

TEST(NurbsInterpolate, ALongCurveIsTheSameOnAnyNumberOfThreads) {
  // Past one block of rows (16384), the rows are filled in blocks on several threads,
  // each walking its spans from the first it was given: the same curve, bit for bit,
  // with and without end derivatives, and through every point.
  std::mt19937 rng(1414);
  const auto q = random_walk(rng, 40000);
  const double scale = magnitude(q);
  for (const bool ends : {false, true}) {
    SCOPED_TRACE(ends ? "end derivatives" : "no end derivatives");
    InterpolationOptions o = with_ends(ends, 1);
    const auto one = nurbs::interpolate(q, o);
    o.threads = 3;
    const auto three = nurbs::interpolate(q, o);
    ASSERT_EQ(one.curve.points.size(), three.curve.points.size());
    ASSERT_EQ(one.curve.knots, three.curve.knots);
    for (std::size_t i = 0; i < one.curve.points.size(); ++i) ASSERT_EQ(one.curve.points[i], three.curve.points[i]) << "control " << i;
    double worst = 0.0;
    for (std::size_t k = 0; k < q.size(); k += 97)
      worst = std::max(worst, glm::distance(nurbs::evaluate(three.curve, three.parameters[k]), q[k]) / scale);
    EXPECT_LE(worst, 1e-9);
  }
}

TEST(NurbsInterpolate, ALongerCurveIsSolvedInWindowsThroughEveryPoint) {
  // Past two windows of rows (65,536 each), the system is solved window by window, each
  // with 128 rows either side: every data point is still met to rounding (a seam between
  // windows that disagreed would miss the points there), with and without end
  // derivatives, evenly and very unevenly spaced, and the same bits on 1 and 3 threads.
  std::mt19937 rng(2026);
  std::vector<Point> uneven{Point(0.0)};
  Point dir(1, 0, 0);
  while (uneven.size() < 200000) {
    dir = glm::normalize(dir + 1.2 * random_cloud(rng, 1)[0]);
    uneven.push_back(uneven.back() + std::exp(uniform(rng, std::log(1e-3), 0.0)) * dir);
  }
  for (const auto& q : {random_walk(rng, 300000), uneven}) {
    const double scale = magnitude(q);
    for (const bool ends : {false, true}) {
      SCOPED_TRACE(std::to_string(q.size()) + (ends ? " points, end derivatives" : " points"));
      InterpolationOptions o = with_ends(ends, 1);
      const auto one = nurbs::interpolate(q, o);
      o.threads = 3;
      const auto three = nurbs::interpolate(q, o);
      ASSERT_EQ(one.parameters, three.parameters);  // made by blocks of steps on 3 threads, summed in order
      ASSERT_EQ(one.curve.knots, three.curve.knots);
      ASSERT_EQ(one.curve.points, three.curve.points);
      double worst = 0.0;
      std::size_t at = 0;
      for (std::size_t k = 0; k < q.size(); ++k) {
        const double off = glm::distance(nurbs::evaluate(three.curve, three.parameters[k]), q[k]) / scale;
        if (off > worst) worst = off, at = k;
      }
      EXPECT_LE(worst, 1e-12) << "at point " << at;
      if (ends) {
        EXPECT_LE(glm::distance(nurbs::derivatives(three.curve, 0.0, 1)[1], *o.start_derivative), 1e-9);
        EXPECT_LE(glm::distance(nurbs::derivatives(three.curve, 1.0, 1)[1], *o.end_derivative), 1e-9);
      }
    }
  }
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
