// The plain loop of the seed paper and the two loop models: Table 1 as printed, loops
// placed on the gauge and sharing end points, the paper model matching an independent
// NURBS implementation, and the smooth model free of the paper's tangent kinks.
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "reference_nurbs.hpp"
#include "support.hpp"

namespace knitc {
namespace {

using yarn_paths::LoopModel;

TEST(PlainLoop, TableMatchesTheSharedCopyOfTable1) {
  const std::filesystem::path csv = test::shared_dir() / "data" / "plain_loop_table1.csv";
  KNITC_NEED_SHARED(csv);
  std::ifstream in(csv);
  std::string line;
  int row = 0;
  const auto table = layout::plain_loop_fractions();
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("point", 0) == 0) continue;
    std::stringstream s(line);
    std::string name, x, y, z;
    std::getline(s, name, ',');
    std::getline(s, x, ',');
    std::getline(s, y, ',');
    std::getline(s, z, ',');
    ASSERT_LT(row, layout::loop_points);
    EXPECT_EQ(name, "P" + std::to_string(row));
    EXPECT_DOUBLE_EQ(table[row].x, std::stod(x)) << name;
    EXPECT_DOUBLE_EQ(table[row].y, std::stod(y)) << name;
    EXPECT_DOUBLE_EQ(table[row].z, std::stod(z)) << name;
    ++row;
  }
  EXPECT_EQ(row, layout::loop_points);
}

TEST(PlainLoop, ScalesByWidthHeightAndThickness) {
  Gauge g{5.0, 6.0, 3.0};
  const auto p = layout::plain_loop(g);
  EXPECT_EQ(p[0], glm::dvec3(0.0));
  EXPECT_DOUBLE_EQ(p[8].x, 2.5);
  EXPECT_DOUBLE_EQ(p[8].y, 6.0);
  EXPECT_DOUBLE_EQ(p[4].z, 0.9999 * 3.0);
  EXPECT_DOUBLE_EQ(p[16].x, 5.0);
  EXPECT_DOUBLE_EQ(g.course_spacing(), 0.86 * 6.0);
}

TEST(Layout, PlacesLoopsOnTheGaugeAndSharesEndPoints) {
  const Pattern p = test::jersey(7, 5, 4.5, 5.0, 2.2);
  const auto layout = layout::lay_out(p);
  ASSERT_EQ(layout.loops.size(), 42u);  // the cast-on's 7 and five rows'
  EXPECT_EQ(layout.courses, 6);
  EXPECT_EQ(layout.wales, 7);
  const double C = 0.86 * 5.0;
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const auto& l = layout.loops[i];
    EXPECT_EQ(l.course, static_cast<int>(i) / 7);
    EXPECT_EQ(l.wale, static_cast<int>(i) % 7);
    EXPECT_NEAR(l.data_points[0].x, l.wale * 4.5, 1e-12);
    EXPECT_NEAR(l.data_points[0].y, l.course * C, 1e-12);
    EXPECT_NEAR(l.data_points[8].y, l.course * C + 5.0, 1e-12);
    // Stockinette flat: every loop a knit loop on the face, in front of the plane.
    EXPECT_GT(l.data_points[4].z, 0.0);
    if (l.wale + 1 < 7) {
      EXPECT_EQ(l.data_points[16], layout.loops[i + 1].data_points[0]);
    }
  }
}

TEST(YarnPaths, PaperModelHasAPiecePerLoopSmoothOnePerYarnTurningAtTheEdges) {
  const auto layout = layout::lay_out(test::jersey(6, 4));
  const auto paper = yarn_paths::trace(layout, LoopModel::paper);
  const auto smooth = yarn_paths::trace(layout, LoopModel::smooth);
  ASSERT_EQ(paper.size(), 30u);
  for (const auto& piece : paper) EXPECT_EQ(piece.data_points.size(), 17u);
  ASSERT_EQ(smooth.size(), 1u);
  const auto& yarn = smooth[0];
  ASSERT_EQ(yarn.loops.size(), 30u);
  for (std::size_t j = 0; j < yarn.loops.size(); ++j) {
    const auto& loop = layout.loops[yarn.loops[j]];
    EXPECT_EQ(loop.order, static_cast<int>(j));
    // Right-side rows (odd courses) run right to left: the loop's points reversed.
    const bool reversed = loop.course % 2 == 1;
    EXPECT_EQ(layout.direction[loop.course], reversed ? -1 : 1);
    for (int k = 0; k < 17; ++k)
      EXPECT_EQ(yarn.data_points[yarn.loop_first[j] + k], loop.data_points[reversed ? 16 - k : k]);
    // Within a course the loops share their ends; between courses the yarn turns outside
    // the edge it reached.
    if (j + 1 < yarn.loops.size()) {
      const auto& next = layout.loops[yarn.loops[j + 1]];
      if (next.course == loop.course) {
        EXPECT_EQ(yarn.loop_first[j + 1], yarn.loop_first[j] + 16);
      } else {
        ASSERT_EQ(yarn.loop_first[j + 1], yarn.loop_first[j] + 19);  // two turning points
        const auto& turn = yarn.data_points[yarn.loop_first[j] + 17];
        EXPECT_TRUE(turn.x < 0.0 || turn.x > 6 * 4.0);
        EXPECT_GT(turn.y, loop.course * 0.86 * 4.2);
        EXPECT_LT(turn.y, next.course * 0.86 * 4.2);
      }
    }
  }
  // A tail at each end, behind the fabric.
  EXPECT_LT(yarn.data_points.front().z, 0.0);
  EXPECT_LT(yarn.data_points.back().z, 0.0);
}

// Paper mode: every loop is interpolated on its own; an independent implementation of
// the same interpolation must give the same centreline, to 1e-6 of W.
TEST(PaperModel, LoopsMatchAnIndependentNurbsImplementation) {
  for (const auto parametrisation : {nurbs::Parametrisation::chord_length, nurbs::Parametrisation::centripetal}) {
    CompileOptions o;
    o.loop_model = LoopModel::paper;
    o.parametrisation = parametrisation;
    const double W = 4.5;
    const Fabric f = compile(test::jersey(5, 4, W, 4.8, 2.4, 1.1), o);
    ASSERT_EQ(f.pieces.size(), 25u);  // 5 stitches, the cast-on and 4 rows
    double worst = 0.0;
    for (const auto& piece : f.pieces) {
      const std::vector<glm::dvec3> q(piece.path.data_points.begin(), piece.path.data_points.end());
      const auto ref = reference::interpolate(q, parametrisation == nurbs::Parametrisation::centripetal);
      for (int i = 0; i <= 400; ++i) {
        const double u = i / 400.0;
        worst = std::max(worst, glm::distance(nurbs::evaluate(piece.curve.curve, u), reference::point(ref, u)));
      }
      // The samples the sweep uses lie on the reference curve too.
      for (std::size_t s = 0; s < piece.samples.size(); ++s)
        worst = std::max(worst, glm::distance(piece.frames.origin[s], reference::point(ref, piece.samples[s])));
    }
    std::printf("paper model vs reference: worst %.3g mm (W = %g mm)\n", worst, W);
    EXPECT_LT(worst, 1e-6 * W);
  }
}

// The turn, in degrees, of the yarn's tangent where each loop meets its right-hand
// neighbour in the course, taken from whichever curve owns each side of the join.
std::vector<double> join_kinks(const Fabric& f) {
  std::vector<const CurvePiece*> owner(f.layout.loops.size());
  std::vector<std::size_t> slot(f.layout.loops.size());
  for (const auto& piece : f.pieces) {
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      owner[piece.path.loops[j]] = &piece;
      slot[piece.path.loops[j]] = j;
    }
  }
  // The curve parameter of a loop's P0 or P16 in its piece.
  auto parameter = [&](std::size_t loop, bool p16) {
    const CurvePiece& piece = *owner[loop];
    const bool reversed = piece.path.loops.size() > 1 && f.layout.direction[f.layout.loops[loop].course] < 0;
    const std::size_t first = piece.path.loop_first[slot[loop]];
    return piece.curve.parameters[first + (p16 != reversed ? 16 : 0)];
  };
  std::vector<double> kinks;
  for (std::size_t i = 0; i + 1 < f.layout.loops.size(); ++i) {
    if (f.layout.loops[i].course != f.layout.loops[i + 1].course) continue;
    const CurvePiece& a = *owner[i];
    const CurvePiece& b = *owner[i + 1];
    const double ua = parameter(i, true);
    const double ub = parameter(i + 1, false);
    const glm::dvec3 ta = glm::normalize(nurbs::derivatives(a.curve.curve, ua, 1)[1]);
    const glm::dvec3 tb = glm::normalize(nurbs::derivatives(b.curve.curve, ub, 1)[1]);
    EXPECT_LT(glm::distance(nurbs::evaluate(a.curve.curve, ua), nurbs::evaluate(b.curve.curve, ub)), 1e-9);
    kinks.push_back(std::atan2(glm::length(glm::cross(ta, tb)), glm::dot(ta, tb)) * 180.0 / std::numbers::pi);
  }
  return kinks;
}

TEST(SmoothModel, TangentTurnsContinuouslyAcrossEveryLoopJoin) {
  // Realistic gauges: W from 4 to 5 yarn diameters, H a little more than W, T = 2 d.
  for (double W : {4.0, 4.5, 5.0}) {
    CompileOptions smooth;
    const Fabric f = compile(test::jersey(6, 3, W, 1.05 * W, 2.0, 1.0), smooth);
    const auto kinks = join_kinks(f);
    ASSERT_EQ(kinks.size(), 20u);  // 5 joins in each of 4 courses
    for (double k : kinks) EXPECT_LT(k, 1e-6) << "W = " << W;
    // One curve per yarn: the join is inside it, where a cubic with simple knots is C2.
    for (const auto& piece : f.pieces) {
      for (std::size_t j = 1; j < piece.path.loops.size(); ++j) {
        const double u = piece.curve.parameters[piece.path.loop_first[j]];
        const auto left = nurbs::derivatives(piece.curve.curve, u - 1e-9, 2);
        const auto right = nurbs::derivatives(piece.curve.curve, u + 1e-9, 2);
        EXPECT_LT(glm::distance(left[2], right[2]), 1e-4 * glm::length(left[2]) + 1e-6);
      }
    }
  }
}

TEST(PaperModel, LeavesTheTangentKinkTheSmoothModelRemoves) {
  // The measurement behind the smooth default: the paper's per-loop curves meet at an
  // angle. Recorded here so a change to the loop data or parameters shows up.
  double lo = 180.0, hi = 0.0;
  for (double W : {4.0, 4.5, 5.0}) {
    for (double T : {1.6, 2.0, 2.5}) {
      CompileOptions paper;
      paper.loop_model = LoopModel::paper;
      const Fabric f = compile(test::jersey(4, 2, W, 1.05 * W, T, 1.0), paper);
      for (double k : join_kinks(f)) {
        lo = std::min(lo, k);
        hi = std::max(hi, k);
      }
    }
  }
  std::printf("paper model join kink: %.1f to %.1f degrees\n", lo, hi);
  EXPECT_GT(lo, 5.0);
  EXPECT_LT(hi, 40.0);
}

TEST(Fabric, BoundingBoxMatchesTheGauge) {
  const int wales = 20, courses = 24;
  const double W = 4.0, H = 4.2, T = 2.0, d = 1.0;
  for (const auto model : {LoopModel::smooth, LoopModel::paper}) {
    CompileOptions o;
    o.loop_model = model;
    const Fabric f = compile(test::jersey(wales, courses, W, H, T, d), o);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const auto& prim : f.mesh.primitives) {
      for (const auto& v : prim.positions) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
    const double C = 0.86 * H;
    // The cast-on is a course too. The smooth model's yarn also turns 0.4 W outside each
    // edge and has a tail 1.1 W long at each end, behind the fabric at -(0.3 T + 0.6 d).
    const bool smooth = model == LoopModel::smooth;
    EXPECT_NEAR(hi.y - lo.y, courses * C + H + d, 0.1 * d);
    if (smooth) {
      EXPECT_GT(hi.x - lo.x, (wales + 0.8) * W);
      EXPECT_LT(hi.x - lo.x, (wales + 2.2) * W + d);
      EXPECT_NEAR(hi.z - lo.z, T + 0.5 * d + 0.3 * T + 0.6 * d + 0.5 * d, 0.1 * d);
    } else {
      EXPECT_NEAR(hi.x - lo.x, wales * W, d);
      EXPECT_NEAR(hi.z - lo.z, T + d, 0.1 * d);
    }
    EXPECT_NEAR(lo.y, -0.5 * d, 0.05 * d);
  }
}

}  // namespace
}  // namespace knitc
