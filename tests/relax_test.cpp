// The relaxation (issues 7 and 16): on the fabrics it must hold for, no two yarn cores
// overlap by more than 5% of a core diameter, no crossing changes sides, no yarn changes
// length by more than 2%; and the result is the same for any thread count. Plus the
// pieces it is made of: capsule distances, the knot-diagram comparison, the boundaries.
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
#include "support.hpp"

namespace knitc {
namespace {

// A library pattern knitted at the seed paper's proportions, loop width 4, loop height
// 4.2, thickness 2 mm, in yarn 1 mm thick: a loop some 16 diameters long, which round
// yarn that does not squash can take. (The library's own gauges with yarns given by
// weight are tighter, about 10 to 12 diameters a loop: see docs/geometry.md.)
Pattern at_paper_gauge(const std::string& name) {
  const std::string path = std::string(KNITC_SOURCE_DIR) + "/patterns/" + name + ".lua";
  std::string source = test::read_text(path);
  source = std::regex_replace(source, std::regex(R"(gauge = \{[^}]*\})"), "gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }");
  source = std::regex_replace(source, std::regex(R"(weight = "[^"]*")"), "diameter = 1.0");
  return runtime::run_pattern(source, path).pattern;
}

// The cores' diameters: the relaxation's chains are refined by them.
std::vector<double> cores(const Pattern& p) {
  std::vector<double> d;
  for (const Yarn& y : p.yarns) d.push_back(y.core_diameter);
  return d;
}

std::vector<yarn::Size> sizes(const Pattern& p) {
  std::vector<yarn::Size> s;
  for (const Yarn& y : p.yarns) s.push_back({y.diameter, y.core_diameter});
  return s;
}

// Centrelines only: the relaxation's figures without the cost of the tubes.
using test::centrelines;

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

TEST(Relax, SameForAnyThreadCount) {
  const std::string source =
      "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
      "knitting = \"flat\" }\ncast_on(10)\nrows(10, \"k1, p1\")\n";
  const Pattern pattern = runtime::run_pattern(source, "rib.lua").pattern;
  CompileOptions one = centrelines(true), two = centrelines(true);
  one.threads = 1;
  two.threads = 3;
  const Fabric a = compile(pattern, one), b = compile(pattern, two);
  ASSERT_EQ(a.pieces.size(), b.pieces.size());
  for (std::size_t i = 0; i < a.pieces.size(); ++i) EXPECT_EQ(a.pieces[i].path.data_points, b.pieces[i].path.data_points);
  EXPECT_EQ(a.relaxation.iterations, b.relaxation.iterations);
}

// A jersey swatch laid out, its chains, and those chains relaxed within `boundary`.
struct Swatch {
  layout::Layout layout;
  std::vector<yarn_paths::Piece> chains;
  relax::Relaxed out;
};
Swatch relaxed_jersey(int stitches, int rows, relax::Boundary boundary) {
  const Pattern pattern = test::jersey(stitches, rows);
  Swatch s;
  s.layout = layout::lay_out(pattern);
  s.chains = relax::refine(yarn_paths::trace(s.layout, yarn_paths::LoopModel::smooth), cores(pattern), relax::Options{}.spacing);
  relax::Options o;
  o.boundary = boundary;
  s.out = relax::relax(s.layout, s.chains, sizes(pattern), o);
  return s;
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

// The repeat is found from the layout: the smallest block of loops that repeats across
// the interior, taken whole times to at least four loops each way.
TEST(Repeat, IsFoundFromTheLayout) {
  auto repeat_of = [](const std::string& body) {
    const std::string source =
        "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
        "knitting = \"flat\" }\n" + body;
    return relax::find_repeat(layout::lay_out(runtime::run_pattern(source, "t.lua").pattern));
  };
  const auto jersey = repeat_of("cast_on(12)\nfor _ = 1, 6 do row \"k\" row \"p\" end\n");
  ASSERT_TRUE(jersey);
  EXPECT_EQ(jersey->wales, 4);    // one wale, four times
  EXPECT_EQ(jersey->courses, 4);  // a knit row and a purl row, twice
  const auto rib = repeat_of("cast_on(18)\nrows(12, \"k3, p3\")\n");
  ASSERT_TRUE(rib);
  EXPECT_EQ(rib->wales, 6);
  EXPECT_EQ(rib->courses, 4);
  EXPECT_FALSE(repeat_of("cast_on(6)\nrows(12, \"k\")\n")) << "no room for a tile inside the edges";
  EXPECT_FALSE(repeat_of("cast_on(12)\nrows(4, \"k\")\nrows(4, \"p\")\nrows(4, \"k1, p1\")\n")) << "bands, not a repeat";
  EXPECT_FALSE(relax::find_repeat(layout::lay_out(at_paper_gauge("half_cardigan")))) << "tucks relax whole";
}

// Where the interior does not repeat throughout, the repeat is still found: a few courses
// at either end that differ (a border) are left out of the interior; round a patch of
// another stitch (a motif on a plain ground, under a tenth of the interior) the block is
// cut where the ground repeats exactly, and the patch's loops are not tiled.
TEST(Repeat, IsFoundWhereTheInteriorMostlyRepeats) {
  auto layout_of = [](const std::string& body) {
    const std::string source =
        "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
        "knitting = \"flat\" }\n" + body;
    return layout::lay_out(runtime::run_pattern(source, "t.lua").pattern);
  };
  const auto bordered = relax::find_repeat(layout_of("cast_on(16)\nrows(4, \"k\")\nfor _ = 1, 8 do row \"k\" row \"p\" end\nrows(4, \"k\")\n"));
  ASSERT_TRUE(bordered) << "garter borders of 4 rows left out";
  EXPECT_EQ(bordered->wales, 4);
  EXPECT_EQ(bordered->course_period, 2);
  EXPECT_GE(bordered->course0, 4);
  // Jersey, 24 x 24, with a 3 x 3 patch of reverse stockinette in its middle.
  std::string motif = "cast_on(24)\n";
  for (int r = 1; r <= 24; ++r) {
    const bool patch = r >= 11 && r <= 13;
    const std::string k = r % 2 == 1 ? "k" : "p", p = r % 2 == 1 ? "p" : "k";
    motif += "row \"" + (patch ? k + "10, " + p + "3, " + k + "11" : k) + "\"\n";
  }
  const layout::Layout with_motif = layout_of(motif);
  const auto repeat = relax::find_repeat(with_motif);
  ASSERT_TRUE(repeat);
  EXPECT_EQ(repeat->wale_period, 1);
  EXPECT_EQ(repeat->course_period, 2);
  // The block lies on the ground, clear of the patch (courses 11 to 13, needles 10 to 12).
  EXPECT_TRUE(repeat->course0 + repeat->courses <= 11 || repeat->wale0 + repeat->wales <= 10 || repeat->wale0 > 12);
  const Pattern pattern = runtime::run_pattern(
      "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
      "knitting = \"flat\" }\n" + motif, "t.lua").pattern;
  // Tiled round the patch, the yarn there started deeper into itself than laid out (the
  // patch's loops blended between the ground's moves either side): refused, relaxed whole,
  // the result as clean either way (tests/knitout_test.cpp has a real program tiled so).
  const Fabric f = compile(pattern, centrelines(true));
  EXPECT_LE(measure::measure(pattern, f.layout, f.pieces).deepest_core_penetration, 0.05);
  EXPECT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
  EXPECT_FALSE(relax::find_repeat(layout_of("cast_on(12)\nrows(4, \"k\")\nrows(4, \"p\")\nrows(4, \"k1, p1\")\nrows(4, \"k\")\n")))
      << "bands, each a quarter of it: no repeat";
}

// Relaxed by its repeat, a swatch's tiled interior is held and its edges relaxed
// against it: the cores clear, and the tile's loop shape is the swatch's.
TEST(Repeat, TiledSwatchClearsAndTakesTheTilesShape) {
  const Pattern pattern = test::jersey(16, 20);
  const Fabric by_repeat = compile(pattern, centrelines(true));
  ASSERT_EQ(by_repeat.relaxation.repeat_wales, 4);
  EXPECT_GT(by_repeat.relaxation.held_share, 0.1);
  EXPECT_LE(measure::measure(pattern, by_repeat.layout, by_repeat.pieces).deepest_core_penetration, 0.05);
  relax::Options tile;
  tile.boundary = relax::Boundary::periodic;
  CompileOptions alone = centrelines(true);
  const Pattern repeat = test::jersey(4, 4);
  alone.relaxation = tile;
  const Fabric periodic = compile(repeat, alone);
  const auto a = measure::loop_shape(by_repeat.layout, by_repeat.pieces);
  ASSERT_GT(periodic.relaxation.period.x, 0.0);
  EXPECT_NEAR(a.wale_pitch, periodic.relaxation.period.x / 4.0, 0.03 * a.wale_pitch);
}

// A tube's interior repeats as flat work's does in its layout's own frame: relaxed by the
// same tile, unrolled and rolled back round the tube, its cores clear and its loops take
// the tile's shape, as a flat swatch's do; a tube too narrow for a flat tile relaxes whole.
TEST(Repeat, ATubeIsRelaxedByItsRepeatRolledRoundIt) {
  auto tube = [](int stitches) {
    const std::string source =
        "pattern { gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0 } }, "
        "knitting = \"round\" }\ncast_on(" + std::to_string(stitches) + ")\nrows(24, \"k\")\n";
    return runtime::run_pattern(source, "tube.lua").pattern;
  };
  const Pattern wide = tube(32);
  const Fabric round = compile(wide, centrelines(true));
  ASSERT_TRUE(round.relaxed);
  EXPECT_EQ(round.relaxation.repeat_wales, 4);
  EXPECT_GT(round.relaxation.held_share, 0.3);
  const auto m = measure::measure(wide, round.layout, round.pieces);
  EXPECT_LE(m.deepest_core_penetration, 0.05);
  // The flat swatch relaxed by the same tile: the same loops.
  const Fabric flat = compile(test::jersey(16, 20), centrelines(true));
  ASSERT_EQ(flat.relaxation.repeat_wales, 4);
  const auto a = measure::loop_shape(round.layout, round.pieces), b = measure::loop_shape(flat.layout, flat.pieces);
  ASSERT_GT(a.loops, 100u);
  EXPECT_NEAR(a.loop_length, b.loop_length, 0.01 * b.loop_length);
  EXPECT_NEAR(a.course_spacing, b.course_spacing, 0.03 * b.course_spacing);
  // Across, the flat loops' spacing at the radius their centres stand out from the tube's
  // middle surface (the layout's z = 0, rolled round 32 of the flat pitches), as the
  // flat loops' centres stand in front of theirs.
  double depth = 0.0;
  int counted = 0;
  for (const auto& piece : flat.pieces)
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const auto& loop = flat.layout.loops[static_cast<std::size_t>(piece.path.loops[j])];
      if (loop.course < 6 || loop.course > 14 || loop.wale < 4 || loop.wale > 11) continue;
      for (std::size_t k = piece.path.loop_first[j]; k <= piece.path.loop_last[j]; ++k, ++counted) depth += piece.path.data_points[k].z;
    }
  ASSERT_GT(counted, 0);
  depth /= counted;
  const double middle = 32.0 * b.wale_pitch / (2.0 * std::numbers::pi);
  EXPECT_NEAR(a.wale_spacing, b.wale_spacing * (middle + depth) / middle, 0.01 * b.wale_spacing) << depth;
  // Round the middle rounds, the loops at the seam (relaxed against the held interior)
  // as far from the axis as the held ones: the tube stays round.
  double seam = 0.0, held = 0.0;
  int seams = 0, helds = 0;
  for (const auto& piece : round.pieces)
    for (std::size_t j = 0; j < piece.path.loops.size(); ++j) {
      const auto& loop = round.layout.loops[static_cast<std::size_t>(piece.path.loops[j])];
      if (loop.course < 10 || loop.course > 14) continue;
      double r = 0.0;
      for (std::size_t k = piece.path.loop_first[j]; k <= piece.path.loop_last[j]; ++k)
        r += std::hypot(piece.path.data_points[k].x, piece.path.data_points[k].z);
      r /= static_cast<double>(piece.path.loop_last[j] + 1 - piece.path.loop_first[j]);
      const bool at_seam = loop.wale < 2 || loop.wale >= round.layout.wales - 2;
      (at_seam ? seam : held) += r;
      ++(at_seam ? seams : helds);
    }
  ASSERT_GT(seams, 0);
  ASSERT_GT(helds, 0);
  EXPECT_NEAR(seam / seams, held / helds, 0.03 * held / helds);
  const Fabric narrow = compile(tube(16), centrelines(true));
  EXPECT_EQ(narrow.relaxation.repeat_wales, 0) << "under least_round_wales: relaxed whole";
}

// The held interior's pressing is found once per tile point and copied to its other
// copies (Relaxed::same_as): the same as pressing every point, and most were copied.
TEST(Repeat, TheInteriorsCopiesArePressedAsIfEachWerePressed) {
  const Pattern pattern = test::jersey(30, 36);
  const auto [layout, chains, out] = relaxed_jersey(30, 36, relax::Boundary::free);
  ASSERT_GT(out.stats.repeat_wales, 0);
  std::size_t points = 0, copies = 0;
  for (const auto& piece : out.pieces) points += piece.data_points.size();
  ASSERT_EQ(out.same_as.size(), points);
  for (std::size_t i = 0; i < points; ++i) copies += out.same_as[i] != i ? 1 : 0;
  EXPECT_GT(copies, points / 5) << "copies of " << points << " points";
  auto each = out.pieces;
  relax::press(each, sizes(pattern), 2);
  double worst = 0.0, most = 0.0;
  for (std::size_t i = 0; i < each.size(); ++i)
    for (std::size_t k = 0; k < each[i].pressed.size(); ++k) {
      worst = std::max(worst, glm::distance(each[i].pressed[k], out.pieces[i].pressed[k]));
      most = std::max(most, glm::length(each[i].pressed[k]));
    }
  EXPECT_GT(most, 0.05) << "the yarns press somewhere";
  EXPECT_LE(worst, 1e-9);  // (1.9e-13 here: the copies lie on the tile to rounding)
}

// The crossings check of a fabric relaxed by repeat looks at the tile's first copies and
// what is not a copy: it finds what the whole check finds there, and counts fewer.
TEST(Repeat, TheCrossingsCheckOfTheCopiesIsTheirFirstCopysCheck) {
  const auto [layout, chains, out] = relaxed_jersey(30, 36, relax::Boundary::free);
  ASSERT_FALSE(out.same_as.empty());
  const auto whole = measure::relaxation_changes(chains, out.pieces, 1.0, 2);
  const auto by_copies = measure::relaxation_changes(chains, out.pieces, 1.0, 2, out.same_as);
  EXPECT_GT(whole.kept, 2 * layout.loops.size());
  EXPECT_GT(by_copies.kept, layout.loops.size() / 4);
  EXPECT_LT(by_copies.kept, whole.kept);
  EXPECT_EQ(measure::passed_through(by_copies), measure::passed_through(whole));
  EXPECT_EQ(by_copies.flipped, whole.flipped);
  // A yarn pushed through another at a point of its own (an edge's) is seen: moved to
  // the far side of the yarn it crosses there.
  auto moved = out.pieces;
  std::size_t at = 0, own = SIZE_MAX;
  for (std::size_t k = 40; k + 40 < moved[0].data_points.size() && own == SIZE_MAX; ++k)
    if (out.same_as[k] == k && out.same_as[k - 1] == k - 1 && out.same_as[k + 1] == k + 1) own = k;
  ASSERT_NE(own, SIZE_MAX);
  for (const auto& c : measure::crossings(out.pieces))
    if (c.piece_a == 0 && c.segment_a >= own && c.segment_a < own + 400 && std::abs(c.depth) > 0.2) {
      at = c.segment_a;
      for (std::size_t k = at - 1; k <= at + 2; ++k) moved[0].data_points[k].z -= 2.0 * c.depth;
      break;
    }
  ASSERT_NE(at, 0u);
  const auto pushed = measure::relaxation_changes(chains, moved, 1.0, 2, out.same_as);
  EXPECT_GT(pushed.flipped + pushed.lost_alone + pushed.found_alone, 0u);
}

TEST(Crossings, OnlyTheCountedAreCountedButAllMatch) {
  yarn_paths::Piece across, up, other;
  across.data_points = {{-1, 0, 0}, {1, 0, 0}};
  up.data_points = {{0, -1, 0.5}, {0, 1, 0.5}};
  other.data_points = {{0.5, -1, 0.5}, {0.5, 1, 0.5}};
  const auto x = measure::crossings({across, up, other});
  ASSERT_EQ(x.size(), 2u);
  // Both gone: only the counted one is lost.
  up.data_points = {{3, -1, 0.5}, {3, 1, 0.5}};
  other.data_points = {{3.5, -1, 0.5}, {3.5, 1, 0.5}};
  const auto y = measure::crossings({across, up, other});
  EXPECT_EQ(measure::compare(x, y, 2, 0, 0.0, {}, {1, 0}, {}).lost, 1u);
  EXPECT_EQ(measure::compare(x, y, 2).lost, 2u);
  // Kept where either side of a match counts.
  EXPECT_EQ(measure::compare(x, x, 2, 0, 0.0, {}, {0, 1}, {0, 0}).kept, 1u);
  EXPECT_EQ(measure::compare(x, x, 2, 0, 0.0, {}, {0, 0}, {1, 0}).kept, 1u);
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

TEST(Crossings, CountsOverAndUnderAndSeesAFlip) {
  yarn_paths::Piece across, up;
  across.data_points = {{-1, 0, 0}, {1, 0, 0}};
  up.data_points = {{0, -1, 0.5}, {0, 1, 0.5}};
  const auto x = measure::crossings({across, up});
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(x[0].piece_a, 0u);
  EXPECT_DOUBLE_EQ(x[0].depth, -0.5);  // the second piece is in front
  up.data_points = {{0, -1, -0.5}, {0, 1, -0.5}};
  const auto y = measure::crossings({across, up});
  const auto c = measure::compare(x, y, 2);
  EXPECT_EQ(c.flipped, 1u);
  EXPECT_EQ(c.kept, 0u);
  up.data_points = {{3, -1, 0.5}, {3, 1, 0.5}};  // moved aside: the crossing is gone
  const auto lost = measure::compare(x, measure::crossings({across, up}), 2);
  EXPECT_EQ(lost.lost, 1u);
}

// Two yarns laid through one point, each bending there (as a twisted stitch's legs are
// laid), cross once, however the point's coordinates round.
TEST(Crossings, AThroughPointCountsOnce) {
  int wrong = 0;
  for (int k = 1; k <= 500; ++k) {
    const glm::dvec3 p(0.0137 * k, 0.0071 * k, 0.0);
    yarn_paths::Piece a, b;
    a.data_points = {p + glm::dvec3(-1.1, -0.3, 0.5), p + glm::dvec3(0, 0, 0.5), p + glm::dvec3(0.9, 0.4, 0.5)};
    b.data_points = {p + glm::dvec3(-0.3, 1.1, 0), p, p + glm::dvec3(0.4, -0.9, 0)};
    wrong += measure::crossings({a, b}).size() == 1u ? 0 : 1;
  }
  EXPECT_EQ(wrong, 0);
}

// A pair of crossings slid in beside a crossing of the same two yarns, the other one in
// front at both (Reidemeister's second move), is not the crossing flipped: the crossing
// slid along and is kept, and the pair is new, together.
TEST(Crossings, APairSlidInBesideACrossingIsNoFlip) {
  yarn_paths::Piece across, wave;
  for (int i = 0; i <= 20; ++i) across.data_points.push_back({i * 0.5, 0.0, 0.0});
  wave.data_points = {{1.0, -1.0, 0.5}, {1.4, 1.0, 0.5}, {4.0, 1.0, 0.5}};  // in front, near x = 1.2
  const auto before = measure::crossings({across, wave});
  ASSERT_EQ(before.size(), 1u);
  // Behind at x = 1.1 and 1.6 (the pair), then in front at x = 2.6 (the crossing, slid).
  wave.data_points = {{1.1, -1.0, -0.5}, {1.1, 1.0, -0.5}, {1.6, 1.0, -0.5}, {1.6, -1.0, -0.5}, {2.0, -1.0, 0.5}, {3.2, 1.0, 0.5}};
  const auto after = measure::crossings({across, wave});
  ASSERT_EQ(after.size(), 3u);
  const auto c = measure::compare(before, after, 12);
  EXPECT_EQ(c.flipped, 0u);
  EXPECT_EQ(c.kept, 1u);
  EXPECT_EQ(c.found, 2u);
  EXPECT_EQ(c.found_alone, 0u);
  // Flipped for real, the crossing still shows.
  wave.data_points = {{1.0, -1.0, -0.5}, {1.4, 1.0, -0.5}, {4.0, 1.0, -0.5}};
  EXPECT_EQ(measure::compare(before, measure::crossings({across, wave}), 12).flipped, 1u);
}

// A yarn's free end drawn back past another yarn unmakes their crossing alone, with no
// yarn through another: told apart from a lone loss in the middle of a yarn, which the
// measure counts as a possible pass-through.
TEST(Crossings, AnEndDrawnBackIsNoPassThrough) {
  yarn_paths::Piece across, tail;
  for (int i = 0; i <= 40; ++i) across.data_points.push_back({i * 0.5 - 10.0, 0.0, 0.0});
  for (int i = 0; i <= 30; ++i) tail.data_points.push_back({0.0, i * 0.5 - 14.0, 0.2});  // ends at y = 1
  const auto before = measure::crossings({across, tail});
  ASSERT_EQ(before.size(), 1u);
  for (auto& p : tail.data_points) p.y -= 2.0;  // drawn back: its end now short of the other yarn
  const auto after = measure::crossings({across, tail});
  ASSERT_EQ(after.size(), 0u);
  const std::vector<std::uint32_t> segments = {40, 30};
  const auto blind = measure::compare(before, after, 12, 24, 1.0);
  EXPECT_EQ(blind.lost_alone_touching, 1u);  // with no lengths given, it could be a pass-through
  const auto seen = measure::compare(before, after, 12, 24, 1.0, segments);
  EXPECT_EQ(seen.lost_alone, 0u);
  EXPECT_EQ(seen.lost_alone_touching, 0u);
  EXPECT_EQ(seen.lost_at_end, 1u);
  EXPECT_EQ(measure::passed_through(seen), 0u);
  // A loss far from both yarns' ends still counts alone: the middle of a long yarn
  // pulled round the end of another, 50 segments away along it.
  yarn_paths::Piece long_across, long_up;
  for (int i = 0; i <= 100; ++i) long_across.data_points.push_back({i * 0.5 - 25.0, 0.0, 0.0});
  for (int i = 0; i <= 300; ++i) long_up.data_points.push_back({0.0, i * 0.5 - 75.0, 0.2});
  const auto long_before = measure::crossings({long_across, long_up});
  ASSERT_EQ(long_before.size(), 1u);
  for (auto& p : long_up.data_points)
    if (p.y > -2.0 && p.y < 2.0) p.x = 30.0;
  const auto long_after = measure::crossings({long_across, long_up});
  ASSERT_EQ(long_after.size(), 0u);
  const auto middle = measure::compare(long_before, long_after, 12, 24, 1.0, {100, 300});
  EXPECT_EQ(middle.lost_at_end, 0u);
  EXPECT_EQ(middle.lost_alone_touching, 1u);
}

}  // namespace
}  // namespace knitc
