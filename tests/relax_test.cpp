// The relaxation (issues 7 and 16): on the fabrics it must hold for, no two yarn cores
// overlap by more than 5% of a core diameter, no crossing changes sides, no yarn changes
// length by more than 2%; and the result is the same for any thread count. Plus the
// pieces it is made of: capsule distances, the boundaries. The knot-diagram comparison:
// tests/crossings_test.cpp.
// The relaxation by a repeat: tests/repeat_test.cpp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "measure/crossings.hpp"
#include "measure/measure.hpp"
#include "nurbs/nurbs.hpp"
#include "relax/contacts.hpp"
#include "relax/press.hpp"
#include "relax/relax.hpp"
#include "relax/repeat.hpp"
#include "relax_support.hpp"
#include "support.hpp"

namespace knitc {
namespace {

using test::at_paper_gauge;
using test::centrelines;
using test::cores;
using test::relaxed_jersey;
using test::yarn_sizes;

class Relaxed : public testing::TestWithParam<std::string> {};

TEST_P(Relaxed, ClearsEveryContactKeepingLengthsAndCrossings) {
  const Pattern pattern = at_paper_gauge(GetParam());
  const Fabric before = compile(pattern, centrelines(false));
  const Fabric after = compile(pattern, centrelines(true));
  ASSERT_TRUE(after.relaxed);
  EXPECT_LT(after.relaxation.iterations, relax::Options{}.max_iterations) << "did not converge";
  const auto m0 = measure::measure(pattern, before.layout, before.pieces), m1 = measure::measure(pattern, after.layout, after.pieces);
  EXPECT_GT(m0.deepest_core_penetration, 0.5);  // the layout's overlap, for scale
  EXPECT_LE(m1.deepest_core_penetration, 0.05);  // the cores never meet; the shells between may be pressed
  for (std::size_t y = 0; y < pattern.yarns.size(); ++y) {
    if (m0.yarn_length[y] == 0.0) continue;
    EXPECT_NEAR(m1.yarn_length[y] / m0.yarn_length[y], 1.0, 0.02) << "yarn " << pattern.yarns[y].id;
  }
  EXPECT_LE(after.relaxation.length_change, 0.02);

  // The knot diagram: the relaxed chains' points are the refined layout's, moved.
  std::vector<yarn_paths::Piece> relaxed;
  for (const CurvePiece& p : after.pieces) relaxed.push_back(p.path);
  const auto laid = relax::refine(yarn_paths::trace(before.layout, yarn_paths::LoopModel::smooth), cores(pattern),
                                  relax::Options{}.spacing);
  ASSERT_EQ(laid.size(), relaxed.size());
  for (std::size_t i = 0; i < laid.size(); ++i) ASSERT_EQ(laid[i].data_points.size(), relaxed[i].data_points.size());
  double thickest = 0.0;
  for (const Yarn& y : pattern.yarns) thickest = std::max(thickest, y.diameter);
  const auto changes = measure::relaxation_changes(laid, relaxed, thickest);
  const auto x0 = measure::crossings(laid);
  // What compile() found, and told the user of, is what the pieces show (counted, where
  // relaxed by repeat, away from the tile's copies only).
  ASSERT_TRUE(after.crossings_checked);
  if (after.crossings.copies_left_out) {
    EXPECT_LT(after.crossings.kept, changes.kept);
  } else {
    EXPECT_EQ(after.crossings.kept, changes.kept);
  }
  EXPECT_EQ(measure::passed_through(after.crossings), measure::passed_through(changes));
  EXPECT_GT(x0.size(), 2 * before.layout.loops.size());  // every loop crosses others, twice at its interlock at least
  EXPECT_EQ(changes.flipped, 0u);
  // Crossings may vanish or appear, but two at a time (the same yarn in front at both),
  // as two yarns slide apart or together without passing through each other; or alone
  // where a yarn's kink twists out, or where the two yarns lay a diameter apart in depth.
  EXPECT_EQ(changes.lost_alone_touching, 0u) << changes.lost_alone << " lost alone";
  EXPECT_EQ(changes.found_alone_touching, 0u) << changes.found_alone << " new alone";
  RecordProperty("crossings", static_cast<int>(x0.size()));
  RecordProperty("lost", static_cast<int>(changes.lost));
  RecordProperty("new", static_cast<int>(changes.found));
  RecordProperty("alone", static_cast<int>(changes.lost_alone + changes.found_alone));
}

// Issue 7's fabrics: the library's stockinette, garter, 1x1 rib, seed, tuck fabrics
// (half and full cardigan), 2x2 cable and stranded colourwork.
INSTANTIATE_TEST_SUITE_P(Fabrics, Relaxed,
                         testing::Values("jersey", "garter", "rib_1x1", "seed", "half_cardigan", "full_cardigan", "cable_2x2",
                                         "stranded"));

// Work in the round is checked too, seen from outside the tube (relax::tube_as_flat, the
// chains unrolled and cut where a round runs into the next): every loop crosses others,
// and relaxed none is passed through. One stretch of the laid yarn pushed in behind the
// yarn it crossed in front of shows as a flip.
TEST(Relax, ATubesCrossingsAreCheckedUnrolledSeenFromOutside) {
  const Pattern pattern = at_paper_gauge("jersey_in_the_round");
  ASSERT_EQ(pattern.knitting, Knitting::round);
  const Fabric after = compile(pattern, centrelines(true));
  ASSERT_TRUE(after.relaxed);
  ASSERT_TRUE(after.crossings_checked);
  EXPECT_GT(after.crossings.kept, 2 * after.layout.loops.size());
  EXPECT_EQ(measure::passed_through(after.crossings), 0u);

  const Fabric before = compile(pattern, centrelines(false));
  const auto laid = relax::refine(yarn_paths::trace(before.layout, yarn_paths::LoopModel::smooth), cores(pattern),
                                  relax::Options{}.spacing);
  double thickest = 0.0;
  for (const Yarn& y : pattern.yarns) thickest = std::max(thickest, y.diameter);
  auto seen = relax::tube_as_flat(before.layout, laid, laid);
  ASSERT_GT(seen.laid.size(), laid.size());  // cut at each round's start
  const auto crossings = measure::crossings(seen.laid);
  const auto same = measure::relaxation_changes(seen.laid, seen.relaxed, thickest);
  EXPECT_EQ(same.kept, crossings.size() - same.ties);
  EXPECT_EQ(measure::passed_through(same), 0u);
  const auto deep = std::find_if(crossings.begin(), crossings.end(), [](const measure::Crossing& c) { return c.depth > 0.3; });
  ASSERT_NE(deep, crossings.end());
  for (std::uint32_t k = deep->segment_a; k <= deep->segment_a + 1; ++k) seen.relaxed[deep->piece_a].data_points[k].z -= 2.0 * deep->depth;
  EXPECT_GE(measure::passed_through(measure::relaxation_changes(seen.laid, seen.relaxed, thickest)), 1u);
}

// A flat swatch at the paper's gauge, `rows` of the written row `row` on `stitches`,
// compiled relaxed on one thread and on three.
std::pair<Fabric, Fabric> on_one_and_three_threads(int stitches, int rows, const std::string& row,
                                                   const relax::Options& relaxation = {}) {
  const std::string source =
      "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
      "knitting = \"flat\" }\ncast_on(" + std::to_string(stitches) + ")\nrows(" + std::to_string(rows) + ", \"" + row + "\")\n";
  const Pattern pattern = runtime::run_pattern(source, "swatch.lua").pattern;
  CompileOptions one = centrelines(true), three = centrelines(true);
  one.relaxation = three.relaxation = relaxation;
  one.threads = 1;
  three.threads = 3;
  return {compile(pattern, one), compile(pattern, three)};
}

TEST(Relax, SameForAnyThreadCount) {
  const auto [a, b] = on_one_and_three_threads(10, 10, "k1, p1");
  ASSERT_EQ(a.pieces.size(), b.pieces.size());
  for (std::size_t i = 0; i < a.pieces.size(); ++i) EXPECT_EQ(a.pieces[i].path.data_points, b.pieces[i].path.data_points);
  EXPECT_EQ(a.relaxation.iterations, b.relaxation.iterations);
}

// A yarn long enough to be worked in spans (relax.cpp, each_piece: its lengths and bending
// span by span, the even spans then the odd) gives the same points on one thread as on
// three. A few sweeps of a whole 40 x 44 jersey, one yarn of over 65,536 chain points.
TEST(Relax, ALongYarnWorkedInSpansIsTheSameForAnyThreadCount) {
  relax::Options few;
  few.by_repeat = false;
  few.max_iterations = 3;
  const auto [a, b] = on_one_and_three_threads(40, 44, "k", few);
  ASSERT_EQ(a.pieces.size(), 1u);
  ASSERT_GE(a.pieces[0].path.data_points.size(), 4u * 16384u) << "too short to be worked in spans";
  EXPECT_EQ(a.pieces[0].path.data_points, b.pieces[0].path.data_points);
}

TEST(Relax, HeldEdgesStayPut) {
  const auto [layout, chains, out] = relaxed_jersey(8, 6, relax::Boundary::held);
  std::size_t held = 0, moved = 0;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const auto& piece = chains[i];
    for (std::size_t j = 0; j < piece.loops.size(); ++j) {
      const int course = layout.loops[static_cast<std::size_t>(piece.loops[j])].course;
      for (std::size_t k = piece.loop_first[j]; k <= piece.loop_last[j]; ++k) {
        const bool edge = course == 0 || course == layout.courses - 1;
        const bool same = out.pieces[i].data_points[k] == piece.data_points[k];
        if (edge) {
          EXPECT_TRUE(same) << "course " << course;
          held += same ? 1 : 0;
        } else {
          moved += same ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(held, 0u);
  EXPECT_GT(moved, 0u);
  EXPECT_LE(out.stats.end_overlap, 0.02) << out.stats.iterations << " sweeps";
}

// One stitch by 300 rows: its sweeps' own passes settle by the 60th, but the height's fit
// kept one sign at 1e-10 a sweep, and the size boost, grown to its cap, moved the strip's
// ends on its own for all 400 sweeps (docs/relaxation.md, "A narrow, tall strip").
TEST(Relax, ANarrowTallStripSettles) {
  const auto [layout, chains, out] = relaxed_jersey(1, 300, relax::Boundary::free);
  EXPECT_LT(out.stats.iterations, 150);
  EXPECT_LE(out.stats.end_overlap, 0.02);
  EXPECT_LE(out.stats.length_change, 0.015);
}

TEST(Relax, PeriodicSwatchClearsContactsAcrossItsEdgesAndDrawsIn) {
  const auto [layout, chains, out] = relaxed_jersey(8, 8, relax::Boundary::periodic);
  EXPECT_GT(out.stats.start_overlap, 0.5);
  EXPECT_LE(out.stats.end_overlap, relax::Options{}.tolerance + 1e-9);
  EXPECT_LT(out.stats.iterations, relax::Options{}.max_iterations);
  EXPECT_LE(out.stats.length_change, 0.02);
  // The first wale's loops met the last wale's images, and were pushed like a middle one:
  // the same shape, one swatch width apart.
  const auto& piece = out.pieces[0];
  auto centre = [&](std::size_t j) {
    glm::dvec3 sum(0.0);
    for (std::size_t k = piece.loop_first[j]; k <= piece.loop_last[j]; ++k) sum += piece.data_points[k];
    return sum / static_cast<double>(piece.loop_last[j] - piece.loop_first[j] + 1);
  };
  // Course 4 (pattern row 4, worked right to left): loops j = 8 * 4 + 0 .. 7 of the piece.
  const glm::dvec3 first = centre(8 * 4), last = centre(8 * 4 + 7), middle = centre(8 * 4 + 3), next = centre(8 * 4 + 4);
  EXPECT_NEAR(first.z - middle.z, 0.0, 0.05) << "an edge loop sits as deep as a middle one";
  EXPECT_NEAR(last.z - next.z, 0.0, 0.05);
  // Across the repeat's edge the loops are as far apart as in the middle.
  ASSERT_GT(out.stats.period.x, 0.0);
  EXPECT_NEAR(std::abs(first.x + out.stats.period.x - last.x), std::abs(next.x - middle.x), 0.05 * std::abs(next.x - middle.x));
  // And up: the cast-on stands one repeat above the last course as a course above its
  // neighbour; the repeat drew in as a swatch does (the layout's courses are 3.61 mm apart,
  // a relaxed jersey swatch's about 2.95), its width kept.
  auto course_y = [&](int k) {
    double y = 0.0;
    for (int w = 0; w < 8; ++w) y += centre(static_cast<std::size_t>(8 * k + w)).y;
    return y / 8.0;
  };
  const int courses = static_cast<int>(layout.courses);
  ASSERT_GT(out.stats.period.y, 0.0);
  const double inner = course_y(5) - course_y(4), seam = course_y(0) + out.stats.period.y - course_y(courses - 1);
  EXPECT_NEAR(seam, inner, 0.1 * inner);
  EXPECT_NEAR(out.stats.period.y / courses, 2.95, 0.3);
  EXPECT_NEAR(out.stats.period.x / 8.0, 4.0, 0.2);
}

TEST(Relax, OffLeavesTheLayoutAsItIs) {
  const Pattern pattern = test::jersey(6, 4);
  const Fabric off = compile(pattern, centrelines(false));
  EXPECT_FALSE(off.relaxed);
  const auto traced = yarn_paths::trace(off.layout, yarn_paths::LoopModel::smooth);
  ASSERT_EQ(traced.size(), off.pieces.size());
  EXPECT_EQ(traced[0].data_points, off.pieces[0].path.data_points);
}

// A relaxation cut short leaves the layout's overlaps (the program warns); a finished one
// clears them. (A real case, a wide full-needle rib over a jersey, takes 15 s to stop
// at its 400 sweeps: docs/knitout.md.)
TEST(Relax, CoresLeftOverlappingAreToldFromASettledFabric) {
  const Pattern pattern = at_paper_gauge("rib_1x1");
  CompileOptions cut_short = centrelines(true);
  cut_short.relaxation.max_iterations = 2;
  const Fabric stopped = compile(pattern, cut_short);
  EXPECT_EQ(stopped.relaxation.iterations, 2);
  EXPECT_TRUE(cores_left_overlapping(stopped, cut_short.relaxation)) << stopped.relaxation.end_overlap;
  const CompileOptions whole = centrelines(true);
  const Fabric settled = compile(pattern, whole);
  EXPECT_FALSE(cores_left_overlapping(settled, whole.relaxation)) << settled.relaxation.end_overlap;
  EXPECT_FALSE(cores_left_overlapping(compile(pattern, centrelines(false)), whole.relaxation));
}

TEST(Relax, RefineKeepsEveryPointAndLoop) {
  const Pattern pattern = test::jersey(4, 3);
  const auto layout = layout::lay_out(pattern);
  const auto traced = yarn_paths::trace(layout, yarn_paths::LoopModel::smooth);
  const auto refined = relax::refine(traced, {1.0}, 0.5);
  ASSERT_EQ(refined.size(), traced.size());
  const auto& a = traced[0];
  const auto& b = refined[0];
  EXPECT_GT(b.data_points.size(), 2 * a.data_points.size());
  for (std::size_t j = 0; j < a.loops.size(); ++j) {
    EXPECT_EQ(b.data_points[b.loop_first[j]], a.data_points[a.loop_first[j]]);
    EXPECT_EQ(b.data_points[b.loop_last[j]], a.data_points[a.loop_last[j]]);
  }
    // The chords between data points are cut into pieces of at most 0.5: on the curve, a
  // little more where it bends.
  for (std::size_t k = 1; k < b.data_points.size(); ++k) EXPECT_LE(glm::distance(b.data_points[k - 1], b.data_points[k]), 0.75);
}

// A long piece's inserted points, found in blocks on two threads, lie on its curve where
// each one's parameter, searched for alone, puts it: the same bits.
TEST(Relax, RefineOnThreadsPutsEachPointOnTheCurveAsSearchedFor) {
  yarn_paths::Piece piece;
  for (int k = 0; k < 20000; ++k)
    piece.data_points.emplace_back(0.9 * k, std::sin(0.37 * k), 0.3 * std::cos(0.11 * k) + (k % 7 == 0 ? 0.4 : 0.0));
  const auto curve = nurbs::interpolate(piece.data_points);
  const auto refined = relax::refine({piece}, {1.0}, 0.35, 2);
  const auto& points = refined[0].data_points;
  ASSERT_GT(points.size(), 2 * piece.data_points.size());
  EXPECT_EQ(relax::refine({piece}, {1.0}, 0.35, 1)[0].data_points, points);
  // Walk the old points through the new: between old k - 1 and k, m - 1 points at
  // parameters j / m of the way.
  std::size_t at = 0;
  for (std::size_t k = 0; k < piece.data_points.size(); ++k) {
    if (k > 0) {
      std::size_t next = at + 1;
      while (points[next] != piece.data_points[k]) ++next;
      const std::size_t m = next - at;
      const double u0 = curve.parameters[k - 1], u1 = curve.parameters[k];
      for (std::size_t j = 1; j < m; ++j)
        ASSERT_EQ(points[at + j], nurbs::derivatives(curve.curve, u0 + (u1 - u0) * static_cast<double>(j) / static_cast<double>(m), 0)[0])
            << k << " " << j;
      at = next;
    }
    ASSERT_EQ(points[at], piece.data_points[k]);
  }
}

// Chains built by hand for the contact tests: a yarn of straight segments as a piece of
// its own, each segment contactable; then the chains closed with a core 0.1 mm and a free
// diameter 0.2 mm everywhere, every point free.
void add_yarn(relax::Chains& c, const std::vector<glm::dvec3>& points) {
  const std::size_t first = c.pos.size();
  for (std::size_t k = 0; k < points.size(); ++k) {
    c.pos.push_back(points[k]);
    c.along.push_back(k == 0 ? 0.0 : c.along.back() + glm::distance(points[k - 1], points[k]));
    c.piece.push_back(static_cast<std::uint32_t>(c.first.size()));
    const bool last = k + 1 == points.size();
    c.segment.push_back(last ? 0 : 1);
    c.contactable.push_back(last ? 0 : 1);
    c.rest_length.push_back(last ? 0.0 : glm::distance(points[k], points[k + 1]));
  }
  c.first.push_back(first);
  c.along_period.push_back(0.0);
}
void close_yarns(relax::Chains& c) {
  c.first.push_back(c.pos.size());
  const std::size_t n = c.pos.size();
  c.rest = c.pos;
  c.radius.assign(n, 0.05);
  c.shell.assign(n, 0.1);
  c.inv_mass.assign(n, 1.0);
  c.on_loop.assign(n, 1);
  c.thickest = 0.2;
  c.thickest_core = 0.1;
}

// Every pair of segments of different yarns counted one by one: the deepest overlap of
// the 0.1 mm cores, and the mean squeeze of the pairs whose 0.2 mm free surfaces press
// (what Contacts::deepest and compression say of the listed pairs); and how many press.
struct EveryPair {
  double deepest = 0.0, squeeze = 0.0;
  std::size_t pressed = 0;
};
EveryPair every_pair(const relax::Chains& c) {
  EveryPair e;
  const std::size_t n = c.pos.size();
  for (std::size_t a = 0; a + 1 < n; ++a)
    for (std::size_t b = a + 1; b + 1 < n; ++b) {
      if (!c.contactable[a] || !c.contactable[b] || c.piece[a] == c.piece[b]) continue;
      double s, t;
      relax::closest_points(c.pos[a], c.pos[a + 1], c.pos[b], c.pos[b + 1], s, t);
      const double dist = glm::distance(glm::mix(c.pos[a], c.pos[a + 1], s), glm::mix(c.pos[b], c.pos[b + 1], t));
      e.deepest = std::max(e.deepest, 0.1 - dist);
      if (dist < 0.2) {
        e.squeeze += 1.0 - std::max(0.0, dist - 0.1) / 0.1;
        ++e.pressed;
      }
    }
  e.squeeze /= static_cast<double>(std::max<std::size_t>(e.pressed, 1));
  return e;
}

// A few segments far longer than the rest (a machine-knit hat's 2.4 mm against a mean of
// 0.33) no longer size the contact grid's cell: the cell allows for twice the mean and
// the long ones search as far as they reach. Every pair is still found: the deepest
// overlap and the mean squeeze of the listed pairs are those of every pair, counted one
// by one. Short yarns in three layers; two long ones across them, one through the
// middle layer's yarns near its ends, far from its midpoint.
TEST(Relax, LongSegmentsAmongShortOnesFindEveryPair) {
  relax::Chains c;
  auto add_piece = [&](const std::vector<glm::dvec3>& points) { add_yarn(c, points); };
  for (int layer = 0; layer < 3; ++layer)
    for (int row = 0; row < 12; ++row) {
      std::vector<glm::dvec3> yarn;
      for (int k = 0; k <= 40; ++k) yarn.push_back({0.3 * k, 0.31 * row + 0.05 * layer, 0.17 * (layer - 1) + 0.01 * std::sin(k + row)});
      add_piece(yarn);
    }
  add_piece({{-0.5, 0.2, 0.02}, {2.6, 1.9, -0.03}, {5.7, 3.2, 0.04}, {8.8, 0.1, 0.0}});
  add_piece({{1.0, 3.6, 0.15}, {4.1, 0.05, -0.1}, {7.0, 3.5, 0.12}});
  close_yarns(c);
  relax::Contacts contacts(glm::dvec2(0.0), relax::contact_margin * c.thickest, false, 2);
  contacts.find(c);
  const EveryPair every = every_pair(c);
  ASSERT_GT(every.pressed, 100u);
  EXPECT_GT(every.deepest, 0.05) << "the long yarns pass through the layers";
  EXPECT_NEAR(contacts.deepest(c), every.deepest, 1e-6);  // (a pair's reach is kept as a float)
  EXPECT_NEAR(contacts.compression(c), every.squeeze, 1e-6);
}

// Where few points have moved past half the margin, find() searches only their segments
// again (Contacts::refind): the rest of the list stands, and the pairs found again are
// kept to twice the margin. No pair that touches may be missed: after each of a dozen
// rounds of a few points pushed into the layer beside them (some of them again and
// again) and the fabric scaled as the size's boost scales it, the listed pairs' deepest
// overlap and mean squeeze are those of every pair counted one by one. (Each of its parts
// was taken out in turn, and the test failed: the moved segments searched among each
// other, and the full search's grid asked where its points are now.)
TEST(Relax, SearchingOnlyTheMovedSegmentsAgainMissesNoPair) {
  relax::Chains c;
  auto add_piece = [&](const std::vector<glm::dvec3>& points) { add_yarn(c, points); };
  for (int layer = 0; layer < 3; ++layer)
    for (int row = 0; row < 12; ++row) {
      std::vector<glm::dvec3> yarn;
      for (int k = 0; k <= 40; ++k) yarn.push_back({0.3 * k, 0.31 * row + 0.05 * layer, 0.2 * (layer - 1) + 0.01 * std::sin(k + row)});
      add_piece(yarn);
    }
  close_yarns(c);
  relax::Contacts contacts(glm::dvec2(0.0), relax::contact_margin * c.thickest, false, 2);
  contacts.find(c);
  std::uint32_t seed = 12345;
  auto next = [&]() { return seed = seed * 1664525u + 1013904223u; };
  double deepest_seen = 0.0;
  for (int round = 0; round < 12; ++round) {
    // Three points of the middle layer's first rows (so some are moved again) pushed a
    // core radius and more toward the layer in front, each with its neighbours, and the
    // front layer's point facing each toward it: pairs of two moved segments.
    for (int k = 0; k < 3; ++k) {
      const std::size_t row = next() % 4, along = 2 + next() % 36;
      for (const std::size_t yarn : {12 + row, 24 + row}) {
        const std::size_t i = c.first[yarn] + along;
        // (Never past z = +-0.07 from the middle of the 0.2 between the layers: they
        // press into each other, but neither passes through, which would count as a
        // crossing kept, not as a distance.)
        const double toward = yarn < 24 ? 1.0 : -1.0, dz = toward * (0.03 + 0.01 * (next() % 4));
        const double dy = 0.02 * (static_cast<int>(next() % 5) - 2);
        for (const std::size_t j : {i - 1, i, i + 1}) {
          const double share = j == i ? 1.0 : 0.5;
          c.pos[j] += glm::dvec3(0.0, share * dy, share * dz);
          c.pos[j].z = toward > 0.0 ? std::min(c.pos[j].z, 0.065) : std::max(c.pos[j].z, 0.135);
        }
      }
    }
    // And two of its next rows toward the layer behind, which stays where it was: pairs
    // of a moved segment and one found only in the full search's grid.
    for (int k = 0; k < 2; ++k) {
      const std::size_t i = c.first[16 + next() % 4] + 2 + next() % 36;
      const double dz = -(0.06 + 0.01 * (next() % 4));
      for (const std::size_t j : {i - 1, i, i + 1}) c.pos[j].z = std::max(c.pos[j].z + (j == i ? 1.0 : 0.5) * dz, -0.13);
    }
    // The size's move: the width grows by 1% about the middle (a sweep's most).
    const double centre = 6.0, grow = 0.01;
    auto move = [&](glm::dvec3& p) { p.x += grow * (p.x - centre); };
    for (auto& p : c.pos) move(p);
    contacts.moved(move, glm::dvec2(1.0 + grow, 1.0));
    if (contacts.stale(c)) contacts.find(c);
    const EveryPair every = every_pair(c);
    deepest_seen = std::max(deepest_seen, every.deepest);
    ASSERT_NEAR(contacts.deepest(c), every.deepest, 1e-6) << "round " << round;  // (a pair's reach is kept as a float)
    ASSERT_NEAR(contacts.compression(c), every.squeeze, 1e-6) << "round " << round;
  }
  EXPECT_GT(deepest_seen, 0.02) << "the moved points press into the layer beside them";
  EXPECT_GE(contacts.refinds(), 6u) << "the moved segments were searched again, not all";
  EXPECT_EQ(contacts.full_finds(), 1u);
}

// Two segments of one yarn that share a point are never a contact, however long: no push
// can part them, and listed, their overlap of a whole core diameter kept the sweeps from
// settling (KnitScript's cable swatch, where the curve through two close data points
// swings wide and refine's segments along it are 0.9 mm long, ran to the 400-sweep limit).
TEST(Relax, SegmentsSharingAPointAreNotAContact) {
  relax::Chains c;
  c.pos = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.5, 0.8, 0.0}};  // 1 mm and 0.94 mm; free d 0.2
  c.rest = c.pos;
  c.radius.assign(3, 0.05);
  c.shell.assign(3, 0.1);
  c.along = {0.0, 1.0, 1.0 + glm::distance(c.pos[1], c.pos[2])};
  c.inv_mass.assign(3, 1.0);
  c.piece.assign(3, 0);
  c.on_loop.assign(3, 1);
  c.segment = {1, 1, 0};
  c.contactable = {1, 1, 0};
  c.rest_length = {1.0, c.along[2] - 1.0, 0.0};
  c.first = {0, 3};
  c.along_period = {0.0};
  c.thickest = 0.2;
  c.thickest_core = 0.1;
  relax::Contacts contacts(glm::dvec2(0.0), relax::contact_margin * c.thickest, false, 1);
  contacts.find(c);
  EXPECT_EQ(contacts.deepest(c), 0.0);
  // A third segment off the yarn's end, lying across the first: a contact.
  c.pos.push_back({0.5, -0.3, 0.05});
  c.pos.push_back({0.5, 0.3, 0.05});
  c.rest = c.pos;
  for (auto* v : {&c.radius}) v->resize(5, 0.05);
  c.shell.resize(5, 0.1);
  c.along.push_back(0.0);
  c.along.push_back(0.6);
  c.inv_mass.resize(5, 1.0);
  c.piece.resize(5, 1);
  c.on_loop.resize(5, 1);
  c.segment = {1, 1, 0, 1, 0};
  c.contactable = {1, 1, 0, 1, 0};
  c.rest_length = {1.0, c.along[2] - 1.0, 0.0, 0.6, 0.0};
  c.first = {0, 3, 5};
  c.along_period = {0.0, 0.0};
  contacts.find(c);
  EXPECT_NEAR(contacts.deepest(c), 0.05, 1e-6);  // 0.1 of reach (a float), 0.05 apart
}

// The shells grow in over sweeps, as the cores' distance does: a pair pressed into its
// shells is pushed no further apart than the shells have grown (switched on whole, every
// pressed pair went out to its free surfaces in one sweep, and the 3x3 cable panel
// passed 25 crossings through in that sweep).
TEST(Relax, ShellsPushNoFurtherThanTheyHaveGrown) {
  auto pressed_pair = [] {  // two crossing segments of two yarns, cores 0.1 mm apart with skin to spare, shells 0.2
    relax::Chains c;
    c.pos = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, -1.0, 0.11}, {0.0, 1.0, 0.11}};
    c.rest = c.pos;
    c.radius.assign(4, 0.05);
    c.shell.assign(4, 0.1);
    c.along = {0.0, 2.0, 0.0, 2.0};
    c.inv_mass.assign(4, 1.0);
    c.piece = {0, 0, 1, 1};
    c.on_loop.assign(4, 1);
    c.segment = {1, 0, 1, 0};
    c.contactable = {1, 0, 1, 0};
    c.rest_length = {2.0, 0.0, 2.0, 0.0};
    c.first = {0, 2, 4};
    c.along_period = {0.0, 0.0};
    c.thickest = 0.2;
    c.thickest_core = 0.1;
    return c;
  };
  auto apart_after_a_sweep = [&](double shells) {
    relax::Chains c = pressed_pair();
    relax::Contacts contacts(glm::dvec2(0.0), relax::contact_margin * c.thickest, false, 1);
    contacts.find(c);
    contacts.push_apart(c, relax::contact_skin, 1.0, shells);
    return c.pos[2].z - c.pos[0].z;
  };
  EXPECT_DOUBLE_EQ(apart_after_a_sweep(0.0), 0.11) << "no shells: the cores are clear, nothing moves";
  const double quarter = apart_after_a_sweep(0.25);
  EXPECT_GT(quarter, 0.11) << "a quarter grown: the shells press";
  EXPECT_LE(quarter, 0.125 + 1e-9) << "but not past a quarter of their thickness";
  EXPECT_NEAR(apart_after_a_sweep(1.0), 0.2, 1e-6) << "grown: out to the free surfaces at once, so pressed";
}

TEST(Relax, ClosestPointsOfSegments) {
  double s, t;
  relax::closest_points({0, 0, 0}, {2, 0, 0}, {1, -1, 1}, {1, 1, 1}, s, t);  // crossing, 1 apart
  EXPECT_DOUBLE_EQ(s, 0.5);
  EXPECT_DOUBLE_EQ(t, 0.5);
  relax::closest_points({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}, s, t);  // in line, end to end
  EXPECT_DOUBLE_EQ(s, 1.0);
  EXPECT_DOUBLE_EQ(t, 0.0);
  relax::closest_points({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, s, t);  // parallel
  EXPECT_NEAR(glm::distance(glm::dvec3(s, 0, 0), glm::dvec3(t, 1, 0)), 1.0, 1e-12);
}

TEST(LoopShape, OfTheLayoutIsItsGauge) {
  const Pattern pattern = test::jersey(12, 10);  // W 4, H 4.2: C = 0.86 H
  const Fabric fabric = compile(pattern, centrelines(false));
  const auto shape = measure::loop_shape(fabric.layout, fabric.pieces);
  EXPECT_EQ(shape.loops, 7u * 8u);  // courses 2..8 of the cast-on and 10 rows, needle positions 2..9
  EXPECT_NEAR(shape.wale_spacing, 4.0, 0.04);
  EXPECT_NEAR(shape.course_spacing, 0.86 * 4.2, 0.04);
  EXPECT_NEAR(shape.kw, shape.loop_length / 4.0, 0.05);
  EXPECT_GT(shape.loop_length, 3.0 * 4.0);  // a loop is some three loop widths of yarn, and more
  EXPECT_LT(shape.loop_length, 5.0 * 4.0);
}

}  // namespace
}  // namespace knitc
