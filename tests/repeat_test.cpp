// The relaxation by a repeat (issues 16, 18 and 20): the repeat found from the layout,
// exactly or where the interior mostly repeats, flat or round a tube; the tiled swatch's
// shape the tile's; the interior's copies pressed and checked as their first copy; a
// start too deep to jump to carried there over sweeps.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "knitout/knitout.hpp"
#include "measure/crossings.hpp"
#include "measure/measure.hpp"
#include "relax/press.hpp"
#include "relax/relax.hpp"
#include "relax/repeat.hpp"
#include "relax/strips.hpp"
#include "relax/tile.hpp"
#include "relax/tube.hpp"
#include "relax_support.hpp"
#include "support.hpp"

namespace knitc {
namespace {

using test::at_paper_gauge;
using test::centrelines;
using test::relaxed_jersey;
using test::yarn_sizes;
namespace fs = std::filesystem;

// Round a tube the grid runs on past a round's start: the loop left of needle 0 is the
// next course's last, the one right of a course's last the course before's needle 0;
// past the first or last course there is none, and a course past either end (a
// neighbourhood's corner) goes round as the nearest does.
TEST(Repeat, ATubesGridRunsOnPastTheRoundsStart) {
  relax::LoopGrid g{3, 4, {}, {4, 4, 4}};
  for (long i = 0; i < 12; ++i) g.at.push_back(100 + i);  // course c, wale w: 100 + 4c + w
  EXPECT_EQ(g(1, 2), 106);
  EXPECT_EQ(g(1, -1), 111);  // course 2, wale 3
  EXPECT_EQ(g(1, 4), 100);   // course 0, wale 0
  EXPECT_EQ(g(0, -5), 111);  // five left of needle 0: a round and one more, course 2, wale 3
  EXPECT_EQ(g(2, -1), -1);
  EXPECT_EQ(g(0, 4), -1);
  EXPECT_EQ(g(-1, -1), 103);  // below the first course, left of needle 0: course 0's last
  EXPECT_EQ(g(3, 4), 108);    // above the last, right of its last: course 2's needle 0
  relax::LoopGrid flat{3, 4, g.at, {}};
  EXPECT_EQ(flat(1, -1), -1);
  EXPECT_EQ(flat(1, 4), -1);
}

// The repeat is found from the layout: the smallest block of loops that repeats across
// the interior, taken whole times to at least four wales and two courses.
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
  EXPECT_EQ(jersey->courses, 2);  // a knit row and a purl row
  const auto rib = repeat_of("cast_on(18)\nrows(12, \"k3, p3\")\n");
  ASSERT_TRUE(rib);
  EXPECT_EQ(rib->wales, 6);
  EXPECT_EQ(rib->courses, 2);
  const auto moss = repeat_of("cast_on(16)\nfor _ = 1, 6 do rows(2, \"k1, p1\") rows(2, \"p1, k1\") end\n");
  ASSERT_TRUE(moss);
  EXPECT_EQ(moss->wales, 4);    // two wales, twice
  EXPECT_EQ(moss->courses, 4);  // its repeat of four rows, once
  EXPECT_FALSE(repeat_of("cast_on(6)\nrows(12, \"k\")\n")) << "no room for a tile inside the edges";
  EXPECT_FALSE(repeat_of("cast_on(12)\nrows(4, \"k\")\nrows(4, \"p\")\nrows(4, \"k1, p1\")\n")) << "bands, not a repeat";
  EXPECT_FALSE(relax::find_repeat(layout::lay_out(at_paper_gauge("half_cardigan")))) << "tucks relax whole";
}

// Where the interior does not repeat throughout, the repeat is still found: a few courses
// at either end that differ (a border) are left out of the interior; round a patch of
// another stitch (a motif on a plain ground, under a tenth of the interior) the block is
// cut where the ground repeats exactly, and the patch's loops are not tiled.
// A machine's full-needle rib: its positions half a loop width (each needle column
// shared by the two beds' loops, docs/knitout.md), its repeat found on that lattice, its
// cast-on left to the edges. Its last column holds the front's loop alone
// (79 back needles to 80 front in CMU's), laid as narrow as the rest: a whole position
// there, tiled, passed 996 of CMU's crossings through.
TEST(Repeat, AFullNeedleRibsRepeatLiesOnItsColumnsLattice) {
  const int n = 20, rows = 16;
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\n";
  for (int i = n; i >= 1; --i) k += "knit - f" + std::to_string(i) + " 1\n";
  k += "releasehook 1\nrack +0.25\n";
  for (int r = 0; r < rows; ++r)
    for (int j = 1; j <= n; ++j) {
      const int i = r % 2 == 0 ? j : n + 1 - j;
      const std::string way = r % 2 == 0 ? "+" : "-", f = "knit " + way + " f" + std::to_string(i) + " 1\n";
      const std::string b = i < n ? "knit " + way + " b" + std::to_string(i) + " 1\n" : "";
      k += r % 2 == 0 ? f + b : b + f;
    }
  const Pattern rib = knitout::import_text(k + "outhook 1\n", "fr.k").pattern;
  EXPECT_EQ(rib.courses.back().widths, std::vector<double>(2 * n - 1, 0.5));
  layout::Layout lattice = layout::lay_out(rib);
  EXPECT_FALSE(relax::find_repeat(lattice)) << "not on the loop width's lattice";
  EXPECT_DOUBLE_EQ(relax::lattice_step(lattice), 0.5 * lattice.loop_width);
  lattice.loop_width = relax::lattice_step(lattice);
  const auto repeat = relax::find_repeat(lattice);
  ASSERT_TRUE(repeat);
  EXPECT_EQ(repeat->wale_period, 2);  // a front loop and a back one
  EXPECT_EQ(repeat->course_period, 2);
  EXPECT_GE(repeat->course0, 2) << "the cast-on, and the rib's first row whose back loops are new, are not the repeat";
  // A fabric with no machine's widths steps by its loop width.
  const layout::Layout plain = layout::lay_out(test::jersey(12, 12));
  EXPECT_EQ(relax::lattice_step(plain), plain.loop_width);
}

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

// Past a break in a mostly repeating interior the repeat runs on shifted: CMU's image tube
// (its two layers' knit/purl diagonals a stitch apart where they meet) in small. Each
// loop is tiled at the one shift its neighbours agree on, so both halves are tiled. (A
// diagonal's loop alone fits several of the tile's places: at the first of them, as
// before, the loops of the shifted half took places that were not neighbours, and none
// of that half was tiled.)
TEST(Repeat, ARepeatRunningOnShiftedIsTiledAtTheShiftItsNeighboursAgreeOn) {
  std::string source =
      "pattern { gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }, yarns = { A = { diameter = 1.0 } }, "
      "knitting = \"round\" }\ncast_on(96)\n";
  for (int r = 0; r < 36; ++r) {
    std::string row;
    for (int w = 0; w < 96; ++w) {
      const int m = ((w - r + (w >= 48 ? 1 : 0)) % 4 + 4) % 4;
      row += std::string(w > 0 ? ", " : "") + (m < 2 ? "k1" : "p1");
    }
    source += "row \"" + row + "\"\n";
  }
  const Pattern pattern = runtime::run_pattern(source, "halves.lua").pattern;
  const layout::Layout layout = layout::lay_out(pattern);
  const auto repeat = relax::find_repeat(layout);
  ASSERT_TRUE(repeat);
  EXPECT_EQ(repeat->wale_period, 4);
  EXPECT_EQ(repeat->course_period, 4);
  ASSERT_LT(repeat->wale0, 40) << "the block is on the first half";
  const auto chains = relax::refine(yarn_paths::trace(layout, yarn_paths::LoopModel::smooth), test::cores(pattern), relax::Options{}.spacing);
  const relax::Unrolled flat = relax::unroll(layout, chains);
  const relax::LoopGrid g = relax::grid_of(layout);
  const auto cut = relax::cut_tile(layout, g, flat.pieces, *repeat);
  ASSERT_TRUE(cut);
  relax::Relaxed as_cut;  // the moves are the tile's whatever it is: unrelaxed, none
  as_cut.pieces = cut->pieces;
  relax::Moves moves = relax::unmoved(flat.pieces, layout.loops.size());
  relax::tile_places(layout, g, flat.pieces, *repeat, *cut, moves);
  relax::tile_moves(*cut, as_cut, relax::LatticeStretch{glm::dvec3(0.0), glm::dvec2(1.0)}, moves);
  // Clear of the rounds' ends, the seam and where the halves meet, every loop is tiled.
  int first = 0, second = 0, untiled = 0;
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    if (loop.course < 8 || loop.course > 28) continue;
    const bool in_first = loop.wale >= 6 && loop.wale <= 41, in_second = loop.wale >= 54 && loop.wale <= 89;
    if (!in_first && !in_second) continue;
    if (!moves.loop_tiled[l]) ++untiled;
    else ++(in_first ? first : second);
  }
  EXPECT_EQ(untiled, 0);
  EXPECT_EQ(first, 21 * 36);
  EXPECT_EQ(second, 21 * 36);
  // Where the halves meet (wales 47 and 48), no place fits both neighbourhoods.
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    if (loop.course >= 8 && loop.course <= 28 && (loop.wale == 47 || loop.wale == 48)) {
      EXPECT_FALSE(moves.loop_tiled[l]) << loop.wale;
    }
  }
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
  relax::press(each, yarn_sizes(pattern), 2);
  double worst = 0.0, most = 0.0;
  for (std::size_t i = 0; i < each.size(); ++i)
    for (std::size_t k = 0; k < each[i].pressed.size(); ++k) {
      worst = std::max(worst, glm::distance(each[i].pressed[k], out.pieces[i].pressed[k]));
      most = std::max(most, glm::length(each[i].pressed[k]));
    }
  EXPECT_GT(most, 0.05) << "the yarns press somewhere";
  EXPECT_LE(worst, 1e-9);  // (1.9e-13 here: the copies lie on the tile to rounding)
}

// An edge's strip is copied along it: the copies away from the corners stand for each
// other too (the cast-on's and the last course's loops across the middle, and the
// selvedges' up the middle), each for a copy on its own band, a whole number of periods
// before it, whose surroundings are its own moved.
TEST(Repeat, AStripsCopiesStandForEachOther) {
  const auto [layout, chains, out] = relaxed_jersey(30, 36, relax::Boundary::free);
  ASSERT_GT(out.stats.strips, 0);
  const auto& piece = out.pieces.front();
  ASSERT_EQ(out.pieces.size(), 1u);
  auto loop_at = [&](std::size_t k) {
    for (std::size_t j = 0; j < piece.loops.size(); ++j)
      if (piece.loop_first[j] <= k && k <= piece.loop_last[j]) return &layout.loops[static_cast<std::size_t>(piece.loops[j])];
    return static_cast<const layout::Loop*>(nullptr);
  };
  std::size_t edge_copies = 0;
  for (std::size_t k = 0; k < piece.data_points.size(); ++k) {
    const layout::Loop* loop = loop_at(k);
    if (!loop || out.same_as[k] == k) continue;
    const bool cast_on = loop->course == 0, selvedge = loop->wale == 0;
    if (!cast_on && !selvedge) continue;
    ++edge_copies;
    const layout::Loop* first = loop_at(out.same_as[k]);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->course == 0, cast_on) << "point " << k;
    EXPECT_EQ(first->wale == 0, selvedge) << "point " << k;
    const glm::dvec3 step = piece.data_points[k] - piece.data_points[out.same_as[k]];
    EXPECT_NEAR(cast_on ? step.y : step.x, 0.0, 1e-9) << "point " << k;
    EXPECT_NEAR(step.z, 0.0, 1e-9) << "point " << k;
  }
  EXPECT_GT(edge_copies, 200u);
}

// CMU's machine-knit 1x1 rib (tests/knitout/SOURCES.md): its tile draws in so far that
// jumping the yarn to the tile's places leaves it deeper into itself than the layout did,
// so the edges' relaxation carries it there over sweeps instead (relax::Start::from). It
// is tiled, no yarn passes through another and the cores clear. And it is narrower than
// plain fabric of its loop length, fully relaxed at w = 0.24 l: Spencer's 1x1 rib is about
// 30% narrower (../shared/research/real-fabric-data.md); relaxed whole, this one came out
// 1% narrower, carried to its tile 19%.
TEST(Repeat, ARibTooDeepToJumpIsCarriedToItsTileOverSweeps) {
  const fs::path file = fs::path(KNITC_SOURCE_DIR) / "tests" / "knitout" / "cmu-rib-1x1.knitout";
  const Pattern rib = knitout::import_text(test::read_text(file), file.filename().string()).pattern;
  const Fabric f = compile(rib, centrelines(true));
  ASSERT_GT(f.relaxation.repeat_wales, 0) << "relaxed whole";
  EXPECT_EQ(f.relaxation.morph_sweeps, relax::morph_sweeps);
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
  EXPECT_FALSE(f.tiling_refused);
  EXPECT_LE(measure::measure(rib, f.layout, f.pieces).deepest_core_penetration, 0.05);
  const auto shape = measure::loop_shape(f.layout, f.pieces);
  const double plain = 0.24 * shape.loop_length;
  EXPECT_GT(shape.wale_pitch / plain, 0.6);
  EXPECT_LT(shape.wale_pitch / plain, 0.9);
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

}  // namespace
}  // namespace knitc
