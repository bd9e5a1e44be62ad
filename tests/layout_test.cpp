// Loop templates placed by the knit graph: each stitch's loop where a knitter would
// draw it, and the yarn paths through them.
#include <algorithm>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "support.hpp"

namespace knitc {
namespace {

using yarn_paths::LoopModel;

Pattern run(const std::string& body, const std::string& knitting = "flat") {
  return runtime::run_pattern("pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 }, "
                              "B = { diameter = 1, color = \"#202080\" } }, knitting = \"" + knitting + "\" }\n" + body,
                              "t.lua")
      .pattern;
}

// The loop in course c (0: the cast-on) at needle position w.
const layout::Loop& at(const layout::Layout& l, int c, int w) {
  for (const auto& loop : l.loops)
    if (loop.course == c && loop.wale == w) return loop;
  throw std::out_of_range("no loop there");
}

TEST(Templates, PurlLoopsAreKnitLoopsSeenFromTheBack) {
  const auto l = layout::lay_out(run("cast_on(4)\nrows(2, \"k1, p1\")\n"));
  // Row 1 worked from the right: positions 3 and 1 are knit, 2 and 0 purl; row 2 the same on the face.
  for (int c = 1; c <= 2; ++c) {
    for (int w = 0; w < 4; ++w) {
      const auto& loop = at(l, c, w);
      const bool knit = w % 2 == 1;
      EXPECT_EQ(loop.shape, knit ? layout::Template::knit : layout::Template::purl);
      EXPECT_NEAR(loop.data_points[4].z, (knit ? 1.0 : -1.0) * 0.9999 * 2.0, 1e-9);
    }
  }
}

TEST(Templates, ATuckLoopLiesBehindAndItsOldLoopSpansTwoCourses) {
  const auto l = layout::lay_out(run("cast_on(3)\nrow \"k1, tuck1, k1\"\nrow \"p\"\n"));
  const double C = 0.86 * 4.2, H = 4.2;
  const auto& tuck = at(l, 1, 1);
  EXPECT_EQ(tuck.shape, layout::Template::tuck);
  for (const auto& p : tuck.data_points) EXPECT_LE(p.z, 1e-12);
  EXPECT_LT(tuck.data_points[8].z, -0.5);
  // The cast-on loop under the tuck reaches up to the loop that knits both off.
  EXPECT_NEAR(at(l, 0, 1).data_points[8].y, H + C, 1e-9);
  EXPECT_NEAR(at(l, 0, 0).data_points[8].y, H, 1e-9);
}

TEST(Templates, ASlippedStitchStretchesAndTheYarnFloatsBehindIt) {
  const auto l = layout::lay_out(run("cast_on(3)\nrow \"k1, sl1 wyib, k1\"\nrow \"p\"\n"));
  const double C = 0.86 * 4.2, H = 4.2, W = 4.0;
  EXPECT_NEAR(at(l, 0, 1).data_points[8].y, H + C, 1e-9);
  EXPECT_THROW(at(l, 1, 1), std::out_of_range);  // no loop made there
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 1u);
  // Between the two loops of row 1 the yarn passes position 1 behind the fabric.
  int behind = 0;
  for (const auto& p : pieces[0].data_points)
    behind += p.y > C - 1e-9 && p.y < C + 1e-9 && p.x > W && p.x < 2 * W && p.z < -0.5;
  EXPECT_EQ(behind, 1);
}

TEST(Templates, DecreasesGatherWithTheLeaningStitchOnTop) {
  // "k1, k2tog, yo, k1" worked from the right edge, and its ssk twin.
  for (const bool k2tog : {true, false}) {
    const auto l = layout::lay_out(run(std::string("cast_on(4)\nrow \"k1, ") + (k2tog ? "k2tog" : "ssk") + ", yo, k1\"\n"));
    // Worked from the right: k1 at 3, the decrease at 2 (through 1 and 2), yo at 1, k1 at 0.
    const auto& left = at(l, 0, 1);
    const auto& right = at(l, 0, 2);
    const double W = 4.0;
    // Both heads are drawn together over the decrease's centre (2.5 W).
    EXPECT_GT(left.data_points[8].x, 1.5 * W + 0.3 * W);
    EXPECT_LT(right.data_points[8].x, 2.5 * W + 0.3 * W);
    // k2tog leans right: the left stitch lies on top; ssk the other way.
    EXPECT_EQ(left.data_points[8].z > right.data_points[8].z, k2tog);
    // The yarn over has no parent: the cast-on loop below it is not pulled up to it.
    EXPECT_NEAR(at(l, 1, 1).data_points[0].y, 0.86 * 4.2, 1e-12);
  }
}

TEST(Templates, CabledStitchesCrossInFrontOrBehind) {
  for (const bool front : {true, false}) {
    const auto l = layout::lay_out(run(std::string("cast_on(4)\nrow \"") + (front ? "C4F" : "C4B") + "\"\n"));
    // The crossing is in the stitches moved (the cast-on's): the two on the right were
    // moved to the left, and in C4F they cross in front.
    const double to_left_z = at(l, 0, 3).data_points[3].z, to_right_z = at(l, 0, 0).data_points[3].z;
    EXPECT_EQ(to_left_z > to_right_z, front);
    EXPECT_GE(std::abs(to_left_z - to_right_z), 1.0);  // a yarn diameter apart where they pass
    // Each leans from where it was knitted to the loop knitted through it: its feet stay,
    // its head is that loop's.
    for (int wale = 0; wale < 4; ++wale) {
      const layout::Loop& moved = at(l, 0, wale);
      const int to = (wale + 2) % 4;  // C4: the halves change places
      EXPECT_NEAR(moved.data_points[0].x, wale * l.loop_width, 1e-9);
      EXPECT_NEAR(moved.data_points[8].x, at(l, 1, to).data_points[8].x, 1e-9);
    }
    // The new loops are knitted upright in needle order, sharing their ends as a plain
    // row's do: no yarn runs back behind the block.
    for (int wale = 0; wale + 1 < 4; ++wale)
      EXPECT_EQ(at(l, 1, wale).data_points[layout::loop_points - 1], at(l, 1, wale + 1).data_points[0]);
  }
}

TEST(Templates, ALoopPulledFurtherThanItsWidthCrossesItsLegsInDepth) {
  // Four yarn overs between two plain stitches: the courses are centred on the plain
  // stitches' mean, so each is pulled two needles along to the loop knitted through it.
  // Its head goes there and its feet stay, so its legs cross; they did at one depth,
  // undecided (CMU's hyperbolic plane: 12 crossings flipped relaxed). The leg on the
  // side it is pulled to passes in front, a yarn's diameter from the other.
  const auto l = layout::lay_out(run("cast_on(8)\nrow \"k1, yo, yo, yo, yo, k1, k3tog, k3tog\"\n"));
  int sheared = 0;
  for (const auto& loop : l.loops) {
    if (loop.course != 0) continue;
    const auto& p = loop.data_points;
    const double pulled = p[8].x - 0.5 * (p[0].x + p[16].x);
    if (std::abs(pulled) < 1.5 * l.loop_width) continue;
    ++sheared;
    const double right_in_front = p[12].z - p[4].z;  // P0..P8 the left leg
    EXPECT_GT(pulled > 0.0 ? right_in_front : -right_in_front, 0.99) << "wale " << loop.wale;
  }
  EXPECT_EQ(sheared, 2);
}

TEST(YarnPathsOfFabrics, AStripeCutsTheYarnAndStartsTheNextWithATail) {
  const auto l = layout::lay_out(run("cast_on(4)\nrows(2, \"k\")\nyarn \"B\"\nrows(2, \"k\")\nyarn \"A\"\nrows(2, \"k\")\n"));
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 3u);  // A below, A above (cut: B's rows between), B
  EXPECT_EQ(pieces[0].yarn, 0);
  EXPECT_EQ(pieces[1].yarn, 0);
  EXPECT_EQ(pieces[2].yarn, 1);
  EXPECT_EQ(pieces[0].loops.size(), 12u);
  EXPECT_EQ(pieces[2].loops.size(), 8u);
  for (const auto& p : pieces) {
    EXPECT_LT(p.data_points.front().z, 0.0);
    EXPECT_LT(p.data_points.back().z, 0.0);
  }
}

TEST(YarnPathsOfFabrics, StrandedWorkFloatsTheOtherColourBehind) {
  const auto l = layout::lay_out(run("cast_on(4)\nrow \"k1, k1 B, k1, k1 B\"\nrow \"p\"\n"));
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 2u);  // A (cast-on to row 2), B (row 1)
  const auto& b = pieces.back();
  EXPECT_EQ(b.yarn, 1);
  EXPECT_EQ(b.loops.size(), 2u);
  // From B's loop at position 3 to its loop at 1 the yarn lies behind position 2.
  const auto first = b.data_points.begin() + static_cast<long>(b.loop_first[0]) + 16;
  const auto second = b.data_points.begin() + static_cast<long>(b.loop_first[1]);
  ASSERT_LT(first, second);
  for (auto p = first + 1; p != second; ++p) EXPECT_LT(p->z, -0.5);
}

// A float's points lie in the middle of their shares of it: where each was placed from
// the last one added, the shares compounded (a float over four stitches had its points
// 0.5, 1.31, 2.68 and 3.40 W from its start, not 0.5, 1.5, 2.5 and 3.5).
TEST(YarnPathsOfFabrics, AFloatsPointsAreEvenlySpaced) {
  const auto l = layout::lay_out(run("cast_on(6)\nrow \"k1, k4 B, k1\"\nrow \"p\"\n"));
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  const auto& a = pieces.front();
  ASSERT_EQ(a.yarn, 0);
  // Row 1 is worked from the right: A's loop at position 5, then its float behind 4..1.
  const auto end = a.data_points.begin() + static_cast<long>(a.loop_last[static_cast<std::size_t>(6)]);
  const auto next = a.data_points.begin() + static_cast<long>(a.loop_first[static_cast<std::size_t>(7)]);
  std::vector<double> x;
  for (auto p = end + 1; p != next; ++p) x.push_back(p->x);
  ASSERT_EQ(x.size(), 4u);  // a point about every loop width
  const double share = (next->x - end->x) / 4.0;
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(x[k], end->x + (static_cast<double>(k) + 0.5) * share, 1e-9) << k;
}

// A long float's points (B knits the first and last of 60 stitches and floats behind the
// 58 between) are never all but equal: a curve through points a nanometre apart (a real
// program's 196 mm float ended so) turned in a cusp there, sampled millions of times.
TEST(YarnPathsOfFabrics, ALongFloatsPointsAreNeverAllButEqual) {
  const Pattern pattern = run("cast_on(60)\nrow \"k1 B, k58, k1 B\"\nrow \"p\"\n");
  const auto l = layout::lay_out(pattern);
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  const auto& b = pieces.back();
  ASSERT_EQ(b.yarn, 1);
  double shortest = 1e300;
  for (std::size_t k = 1; k < b.data_points.size(); ++k) shortest = std::min(shortest, glm::distance(b.data_points[k - 1], b.data_points[k]));
  EXPECT_GE(shortest, 1e-3);
  // And its curve is sampled as a float's length asks, not millions of times.
  CompileOptions o;
  o.relax = false;
  const Fabric fabric = compile(pattern, o);
  std::size_t samples = 0;
  for (const auto& piece : fabric.pieces)
    if (piece.path.yarn == 1) samples += piece.samples.size();
  EXPECT_LT(samples, 2000u);
}

// Quilting: a float slipped wyif on row 1 is caught by the knit under it on row 3, which
// lifts its middle two courses up, over the head of the loop the catching stitch is
// pulled through and under the catching loop's legs.
TEST(YarnPathsOfFabrics, ACaughtFloatIsLiftedIntoTheLoopThatCatchesIt) {
  const Pattern p = run("cast_on(5)\nrow \"k1, sl3 wyif, k1\"\nrow \"p\"\nrow \"k2, k under float, k2\"\nrow \"p\"\n");
  const auto g = knit_graph::build(p);
  ASSERT_EQ(g.floats.size(), 1u);
  const int catcher = g.floats[0].caught_by;
  ASSERT_GE(catcher, 0);
  EXPECT_EQ(g.loops[static_cast<std::size_t>(catcher)].course, 3);
  EXPECT_EQ(g.loops[static_cast<std::size_t>(catcher)].slot, 2);
  const auto l = layout::lay_out(p, g);
  ASSERT_EQ(l.float_lifts.size(), 1u);
  ASSERT_EQ(l.float_lifts[0].size(), 3u);
  const glm::dvec3 lift = l.float_lifts[0][1];
  const auto& catching = l.loops[static_cast<std::size_t>(catcher)];
  const auto& parent = at(l, 2, 2);
  EXPECT_NEAR(lift.x, parent.data_points[8].x, 1e-9);
  EXPECT_GT(lift.y, 2.5 * l.course_spacing);  // from course 1 up into course 3's foot
  EXPECT_LT(lift.y, parent.data_points[8].y);
  EXPECT_GT(lift.z, parent.data_points[8].z);  // over the parent's head
  EXPECT_LT(lift.z, catching.data_points[2].z);  // under the catching loop's legs
  // The yarn goes through the lift point between its loops at positions 0 and 4 of row 1.
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 1u);
  const auto& points = pieces[0].data_points;
  EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](const glm::dvec3& q) { return glm::distance(q, lift) < 1e-9; }));
}

// A nupp's five loops share the one stitch's width, so its row is as wide as the rows
// around it and the stitches beside it stay over their parents.
TEST(Templates, ANuppBunchesItsFiveLoopsIntoOneStitchWidth) {
  const auto l = layout::lay_out(run("cast_on(5)\nrow \"k\"\nrow \"p\"\nrow \"k2, nupp, k2\"\nrow \"p2, p5tog, p2\"\n"));
  const double W = 4.0;
  ASSERT_EQ(l.needle[3], 9);
  for (int c = 0; c < l.courses; ++c) EXPECT_NEAR(layout::course_width(l, c), 5 * W, 1e-9) << "course " << c;
  EXPECT_NEAR(l.origin_x[3], l.origin_x[2], 1e-9);
  for (int w = 2; w < 7; ++w) {
    const auto& loop = at(l, 3, w);
    EXPECT_NEAR(loop.data_points[16].x - loop.data_points[0].x, W / 5, 1e-9);
  }
  // The loops beside the nupp sit where the loops below them do.
  EXPECT_NEAR(at(l, 3, 8).data_points[0].x, at(l, 2, 4).data_points[0].x, 1e-9);
  // Neighbours in the bunch lie at different depths.
  EXPECT_GT(std::abs(at(l, 3, 3).data_points[4].z - at(l, 3, 4).data_points[4].z), 0.5);
}

// Wrap 3: three knits, each through its own stitch, then the yarn wound twice round
// them: between the group's last worked loop and the next, the yarn passes in front of
// the three and behind them, twice, within the group's width and up its legs.
TEST(YarnPathsOfFabrics, AWrapWindsTheYarnRoundItsGroupInFrontAndBehind) {
  const Pattern p = run("cast_on(5)\nrow \"k\"\nrow \"p\"\nrow \"k1, wrap 3, k1\"\nrow \"p\"\n");
  const auto g = knit_graph::build(p);
  ASSERT_EQ(g.wraps.size(), 1u);
  const auto& w = g.wraps[0];
  EXPECT_EQ(w.course, 3);
  EXPECT_EQ(w.last - w.first, 2);
  EXPECT_EQ(w.turns, 2);
  for (int i = w.first; i <= w.last; ++i) EXPECT_EQ(g.loops[static_cast<std::size_t>(i)].parents.size(), 1u);
  const auto l = layout::lay_out(p, g);
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 1u);
  const auto& piece = pieces[0];
  // Row 3 is worked from the right: the group's leftmost loop is its last, then position 0.
  const auto last = std::find(piece.loops.begin(), piece.loops.end(), w.first) - piece.loops.begin();
  ASSERT_LT(static_cast<std::size_t>(last + 1), piece.loops.size());
  const double left = at(l, 3, 1).data_points[0].x, right = at(l, 3, 3).data_points[16].x;
  int front = 0, behind = 0;
  for (std::size_t k = piece.loop_last[static_cast<std::size_t>(last)] + 1; k < piece.loop_first[static_cast<std::size_t>(last) + 1]; ++k) {
    const glm::dvec3& q = piece.data_points[k];
    EXPECT_GT(q.x, left - 0.2 * 4.0);
    EXPECT_LT(q.x, right + 0.2 * 4.0);
    EXPECT_GT(q.y, 3 * l.course_spacing);
    if (q.z >= l.float_in_front - 1e-9) ++front;
    if (q.z <= l.float_behind + 1e-9) ++behind;
  }
  EXPECT_GE(front, 2 * 3);  // each turn's pass in front spans the three loops
  EXPECT_GE(behind, 2 * 3);
}

// Bound off at the start of a row: the three are knitted and passed over, lying over
// toward the next (the bind-off template), off the needle; the stitches left stay over
// the loops they were pulled through, and so do the next row's, at the other edge.
TEST(Templates, StitchesBoundOffInARowLeaveTheRestInPlace) {
  const Pattern p = run("cast_on(8)\nrow \"k\"\nrow \"p\"\nrow \"BO 3 sts, k to end\"\nrow \"BO 2 sts, p to end\"\nrow \"k\"\n");
  const auto g = knit_graph::build(p);
  EXPECT_EQ(g.needle, (std::vector<int>{8, 8, 8, 5, 3, 3}));
  EXPECT_EQ(g.columns, (std::vector<int>{8, 8, 8, 8, 5, 3}));
  int bound = 0;
  for (const auto& k : g.loops) bound += k.bound;
  EXPECT_EQ(bound, 5);
  const auto l = layout::lay_out(p, g);
  for (std::size_t i = 0; i < g.loops.size(); ++i) {
    const auto& k = g.loops[i];
    if (k.course < 3 || k.parents.size() != 1) continue;
    const auto& parent = l.loops[static_cast<std::size_t>(k.parents.front())];
    const auto& loop = l.loops[i];
    EXPECT_NEAR(loop.data_points[0].x, parent.data_points[0].x, 1e-9) << "course " << k.course << " column " << k.slot;
    if (k.bound) {
      EXPECT_EQ(loop.shape, layout::Template::bind_off);
    }
  }
  // Row 3 is worked from the right: its bound stitches are the rightmost three.
  EXPECT_TRUE(g.loops[static_cast<std::size_t>(g.course_first[3] + 7)].bound);
  EXPECT_FALSE(g.loops[static_cast<std::size_t>(g.course_first[3] + 4)].bound);
}

// With nothing slipped below it, a stitch worked under the loose strand is refused.
TEST(YarnPathsOfFabrics, AStitchUnderNoFloatIsRefused) {
  const Pattern p = run("cast_on(3)\nrow \"k\"\nrow \"p\"\nrow \"k1, k under float, k1\"\n");
  EXPECT_THROW(knit_graph::build(p), knit_graph::RowError);
}

TEST(YarnPathsOfFabrics, InTheRoundTheYarnSpiralsRoundATube) {
  const int n = 10;
  const Pattern p = run("cast_on(" + std::to_string(n) + ")\nrows(4, \"k\")\n", "round");
  const auto l = layout::lay_out(p);
  const auto pieces = yarn_paths::trace(l, LoopModel::smooth);
  ASSERT_EQ(pieces.size(), 1u);
  const double W = 4.0, C = 0.86 * 4.2, R = n * W / (2.0 * std::numbers::pi);
  // Every sinker point (P0 of a loop) on the circle of the tube's radius, climbing one
  // course spacing per round; consecutive points never far apart.
  const auto& yarn = pieces[0];
  for (std::size_t j = 0; j < yarn.loops.size(); ++j) {
    const auto& q = yarn.data_points[yarn.loop_first[j]];
    EXPECT_NEAR(std::hypot(q.x, q.z), R, 1e-9);
  }
  for (std::size_t i = 1; i < yarn.data_points.size(); ++i)
    EXPECT_LT(glm::distance(yarn.data_points[i - 1], yarn.data_points[i]), 0.7 * W);
  const auto& first = yarn.data_points[yarn.loop_first.front()];
  const auto& last = yarn.data_points[yarn.loop_first.back() + 16];
  EXPECT_NEAR(last.y - first.y, 5 * C, 1e-9);  // the cast-on round and four more
}

// Unrolling a point of the tube and rolling it back gives the point, whichever round's
// place it was unrolled next to; unrolled next to its own place, a local point comes back.
TEST(YarnPathsOfFabrics, ATubesPointUnrollsAndRollsBack) {
  const double circumference = 96.0, climb = 3.6;
  for (const glm::dvec3 local : {glm::dvec3(1.5, 10.0, 0.4), glm::dvec3(47.0, 3.0, -0.7), glm::dvec3(95.9, 30.0, 1.0)}) {
    const glm::dvec3 q = layout::roll(local, circumference, climb);
    const glm::dvec3 back = layout::unroll(q, circumference, climb, local.x + 0.3 * circumference);
    EXPECT_LT(glm::distance(back, local), 1e-9);
    for (const double near : {-circumference, 0.0, 2.5 * circumference}) {
      const glm::dvec3 other = layout::unroll(q, circumference, climb, near);
      EXPECT_LE(std::abs(other.x - near), 0.5 * circumference + 1e-9);
      EXPECT_LT(glm::distance(layout::roll(other, circumference, climb), q), 1e-9);
    }
  }
}

}  // namespace
}  // namespace knitc

namespace knitc {
namespace {

// A bobble's rows stand out of the face, in front of every loop of the fabric, within a
// few loop widths of its stitch; its turned rows are worked against their course.
TEST(Templates, ABobbleStandsOutOfTheFaceAndItsTurnedRowsRunBack) {
  const auto l = layout::lay_out(run("cast_on(5)\nrow \"k\"\nrow \"p\"\nrow \"k2, MB, k2\"\nrow \"p\"\n"));
  ASSERT_EQ(l.bobbles.size(), 1u);
  const auto& b = l.bobbles.front();
  const double W = 4.0, T = 2.0;
  double front = 0.0, fabric_front = 0.0;
  for (std::size_t i = 0; i < l.loops.size(); ++i) {
    const bool in_bobble = static_cast<int>(i) >= b.first && static_cast<int>(i) < b.gathered();
    for (const auto& p : l.loops[i].data_points) {
      if (in_bobble) {
        front = std::max(front, p.z);
        EXPECT_LT(std::abs(p.x - 2.5 * W), 2.0 * W);
      } else {
        fabric_front = std::max(fabric_front, p.z);
      }
    }
  }
  EXPECT_GT(front, fabric_front + T);
  for (int r = 0; r < b.rows; ++r)
    EXPECT_EQ(layout::way(l, static_cast<std::size_t>(b.first + r * b.loops)), r % 2 ? 1 : -1) << "row " << r;
  EXPECT_EQ(layout::way(l, static_cast<std::size_t>(b.gathered())), -1);
}

}  // namespace
}  // namespace knitc
