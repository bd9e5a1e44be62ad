// The edges of a fabric relaxed by its repeat, as strips periodic along each edge
// (relax/strips.hpp, issue 18): each band is one strip's copies, exactly a period apart,
// and the fabric is the one the bands relaxed whole give, to a small part of the yarn's
// diameter; a swatch too small for a strip keeps its bands relaxed whole.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "measure/crossings.hpp"
#include "measure/measure.hpp"
#include "support.hpp"

namespace knitc {
namespace {

CompileOptions centrelines(bool strips) {
  CompileOptions o = test::centrelines(true);
  o.relaxation.by_strips = strips;
  return o;
}

// A loop's data points by its place.
std::vector<glm::dvec3> points_of(const Fabric& f, int course, int wale) {
  for (const auto& piece : f.pieces)
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const auto& loop = f.layout.loops[static_cast<std::size_t>(piece.path.loops[j])];
      if (loop.course == course && loop.wale == wale)
        return {piece.path.data_points.begin() + static_cast<std::ptrdiff_t>(piece.path.loop_first[j]),
                piece.path.data_points.begin() + static_cast<std::ptrdiff_t>(piece.path.loop_last[j] + 1)};
    }
  return {};
}

// The largest difference of a - b from one step over every point, or infinity if the
// loops differ in points.
double off_one_step(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  if (a.size() != b.size() || a.empty()) return INFINITY;
  const glm::dvec3 step = a[0] - b[0];
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, glm::length(a[k] - b[k] - step));
  return worst;
}

struct Both {
  Pattern pattern;
  Fabric strips, whole;
};
const Both& jersey_48() {
  static const Both both = [] {
    Both b;
    b.pattern = test::jersey(48, 44);
    b.strips = compile(b.pattern, centrelines(true));
    b.whole = compile(b.pattern, centrelines(false));
    return b;
  }();
  return both;
}

TEST(Strips, EachBandIsOneStripsCopiesAPeriodApart) {
  const Fabric& f = jersey_48().strips;
  ASSERT_EQ(f.relaxation.repeat_wales, 4);
  EXPECT_EQ(f.relaxation.strips, 4);
  EXPECT_GT(f.relaxation.strip_share, 0.1);
  // Along the cast-on and the last course: the loops of one course a period apart are the
  // same loop moved, to rounding, across the middle; so are the selvedges' loops up.
  for (const int course : {0, 1, f.layout.courses - 1}) {
    const auto a = points_of(f, course, 16), b = points_of(f, course, 20), c = points_of(f, course, 28);
    EXPECT_LE(off_one_step(b, a), 1e-9) << "course " << course;
    EXPECT_LE(off_one_step(c, b), 1e-9) << "course " << course;
    ASSERT_FALSE(a.empty());
    const glm::dvec3 step = b[0] - a[0];
    EXPECT_NEAR(step.y, 0.0, 1e-9);
    EXPECT_NEAR(step.z, 0.0, 1e-9);
    EXPECT_NEAR(step.x, 4 * 3.94, 0.4) << "four relaxed wales";
  }
  for (const int wale : {0, f.layout.wales - 1}) {
    const auto a = points_of(f, 16, wale), b = points_of(f, 20, wale);
    EXPECT_LE(off_one_step(b, a), 1e-9) << "wale " << wale;
    ASSERT_FALSE(a.empty());
    EXPECT_NEAR((b[0] - a[0]).x, 0.0, 1e-9);
  }
}

TEST(Strips, TheFabricIsTheOneItsBandsRelaxedWholeGive) {
  const Both& both = jersey_48();
  EXPECT_EQ(both.whole.relaxation.strips, 0);
  ASSERT_EQ(both.strips.pieces.size(), both.whole.pieces.size());
  double worst = 0.0, sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < both.strips.pieces.size(); ++i) {
    const auto& a = both.strips.pieces[i].path.data_points;
    const auto& b = both.whole.pieces[i].path.data_points;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double d = glm::distance(a[k], b[k]);
      worst = std::max(worst, d);
      sum += d;
      ++n;
    }
  }
  // (0.14 mm at most here, at the loose last course; 0.004 mm on average.)
  EXPECT_LE(worst, 0.3) << "mm, of a 1 mm yarn";
  EXPECT_LE(sum / static_cast<double>(n), 0.02);
  const auto measured = measure::measure(both.pattern, both.strips.layout, both.strips.pieces);
  EXPECT_LE(measured.deepest_core_penetration, 0.05);
  EXPECT_EQ(measure::passed_through(both.strips.crossings), 0u);
  const auto a = measure::loop_shape(both.strips.layout, both.strips.pieces), b = measure::loop_shape(both.whole.layout, both.whole.pieces);
  EXPECT_NEAR(a.wale_pitch, b.wale_pitch, 0.005 * b.wale_pitch);
  EXPECT_NEAR(a.course_pitch, b.course_pitch, 0.005 * b.course_pitch);
}

// 16 rows leave too few courses between the top and bottom bands for four of the tile's
// 2-course periods and one more, which a strip up the selvedge needs to pay (18 rows do).
TEST(Strips, ASwatchTooSmallForAStripRelaxesItsBandsWhole) {
  const Fabric f = compile(test::jersey(16, 16), centrelines(true));
  ASSERT_EQ(f.relaxation.repeat_wales, 4);
  EXPECT_EQ(f.relaxation.strips, 0);
}

}  // namespace
}  // namespace knitc
