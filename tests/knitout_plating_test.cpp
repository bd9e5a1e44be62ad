// Knitout in and out: plating, a stitch knitted with two carriers' yarns at once, the
// second's loop on the first's technical face.
#include <gtest/gtest.h>

#include <string>

#include "compile.hpp"
#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"
#include "layout/layout.hpp"
#include "measure/crossings.hpp"
#include "support.hpp"

using namespace knitc;
using namespace knitc::knitout;

namespace {

// `n` needles cast on with carrier 1 (alternate tucks on `bed` of each needle), then
// `rows` rows knitted with carriers "1 2" on the needles `bed_of` names: a plated jersey
// when all are front needles, a plated 1x1 rib when they alternate.
template <typename Bed>
std::string plated(int n, int rows, Bed bed_of, const std::string& carriers = "1 2") {
  std::string k = ";!knitout-2\n;;Carriers: 1 2 3\ninhook 1\n";
  for (int i = n; i >= 1; --i) k += "tuck - " + std::string(bed_of(i)) + std::to_string(i) + " 1\n";
  for (int i = 1; i <= n; ++i) k += "knit + " + std::string(bed_of(i)) + std::to_string(i) + " 1\n";
  k += "releasehook 1\nin 2\nin 3\n";  // the yarn inserting hook released before the others come in
  for (int r = 0; r < rows; ++r)
    for (int j = 1; j <= n; ++j) {
      const int i = r % 2 == 0 ? n + 1 - j : j;
      k += "knit " + std::string(r % 2 == 0 ? "- " : "+ ") + bed_of(i) + std::to_string(i) + " " + carriers + "\n";
    }
  return k + "outhook 1\nouthook 2\nouthook 3\n";
}

// A plated jersey of `n` needles as MI-Lab's program starts one: carrier 2 brought in on
// a fixation of its own (tucks and a row on 7 needles right of the fabric), which is
// dropped after two plated rows.
std::string plated_after_a_fixation(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1 2\ninhook 1\n";
  for (int i = n; i >= 1; --i) k += "tuck - f" + std::to_string(i) + " 1\n";
  for (int i = 1; i <= n; ++i) k += "knit + f" + std::to_string(i) + " 1\n";
  k += "inhook 2\n";
  for (int i = n + 9; i >= n + 3; i -= 2) k += "tuck - f" + std::to_string(i) + " 2\n";
  for (int i = n + 4; i <= n + 8; i += 2) k += "tuck + f" + std::to_string(i) + " 2\n";
  for (int i = n + 9; i >= n + 3; --i) k += "knit - f" + std::to_string(i) + " 2\n";
  k += "releasehook 2\n";
  for (int r = 0; r < rows; ++r) {
    for (int j = 1; j <= n; ++j) {
      const int i = r % 2 == 0 ? n + 1 - j : j;
      k += "knit " + std::string(r % 2 == 0 ? "- f" : "+ f") + std::to_string(i) + " 1 2\n";
    }
    if (r == 1)
      for (int i = n + 3; i <= n + 9; ++i) k += "drop f" + std::to_string(i) + "\n";
  }
  return k + "outhook 1\nouthook 2\n";
}

const char* front_bed(int) { return "f"; }
const char* rib_bed(int i) { return i % 2 == 0 ? "f" : "b"; }

}  // namespace

TEST(KnitoutPlating, EachStitchKnittedWithTwoCarriersHasBothYarnsLoopsTheSecondOnItsFace) {
  const Imported in = import_text(plated(12, 8, front_bed), "plated.k");
  EXPECT_TRUE(in.warnings.empty()) << in.warnings.front();
  const Pattern& p = in.pattern;
  ASSERT_EQ(p.yarns.size(), 2u);
  int plated_ops = 0;
  for (const Course& c : p.courses)
    for (const Op& op : c.ops) {
      if (op.plated < 0) continue;
      EXPECT_EQ(op.yarn, 0);
      EXPECT_EQ(op.plated, 1);
      ++plated_ops;
    }
  EXPECT_EQ(plated_ops, 8 * 12);
  // The knit graph: each plated stitch two loops, the second yarn's through the same
  // parents, and the next row's loop pulled through both.
  const knit_graph::Graph g = knit_graph::build(p);
  int plating = 0, through_both = 0;
  for (std::size_t i = 0; i < g.loops.size(); ++i) {
    const auto& l = g.loops[i];
    if (l.plating) {
      ++plating;
      EXPECT_EQ(l.yarn, 1);
      const auto& first = g.loops[i - 1];
      EXPECT_EQ(first.yarn, 0);
      EXPECT_EQ(l.parents, first.parents);
      EXPECT_EQ(l.slot, first.slot);
      EXPECT_EQ(l.course, first.course);
    }
    if (l.parents.size() == 2 && g.loops[static_cast<std::size_t>(l.parents[1])].plating) ++through_both;
  }
  EXPECT_EQ(plating, 8 * 12);
  EXPECT_EQ(through_both, 7 * 12 * 2);  // rows 2 to 8, both yarns' loops
  // Laid: the second yarn's loop in front of the first's (a knit's technical face), by
  // their diameters' mean.
  const layout::Layout laid = layout::lay_out(p);
  for (std::size_t i = 0; i < laid.loops.size(); ++i) {
    if (!laid.loops[i].plating) continue;
    const double d = 0.5 * (p.yarns[0].diameter + p.yarns[1].diameter);
    EXPECT_NEAR(laid.loops[i].data_points[8].z - laid.loops[i - 1].data_points[8].z, d, 1e-9) << "loop " << i;
  }
}

TEST(KnitoutPlating, PlatedJerseyAndRibRelaxWithNoYarnThroughAnother) {
  // Laid straight forward of its first yarn's loop, the plating yarn's lay on its line
  // seen from the face: 58 of a 20-needle jersey's 7,276 crossings were lost where they
  // touched (docs/knitout.md, "Plating").
  for (const auto& [name, text] : {std::pair{"jersey", plated(16, 14, front_bed)}, std::pair{"rib", plated(16, 14, rib_bed)}}) {
    const Pattern p = import_text(text, std::string(name) + ".k").pattern;
    const Fabric f = compile(p, test::centrelines(true));
    ASSERT_TRUE(f.crossings_checked) << name;
    EXPECT_EQ(measure::passed_through(f.crossings), 0u) << name;
  }
}

TEST(KnitoutPlating, ACourseThroughPlatedStitchesLinesUpOverThem) {
  // Each loop pulled through a plated stitch has two parents, the stitch's two yarns'
  // loops: one stitch, over which the layout lines the course up. Counted as a decrease
  // (no plain loop in the course), the course after the fixation's drop, 7 columns
  // narrower, was centred over the one below: 3.5 columns off, and relaxed, about 200 of its
  // 3,966 crossings passed through.
  const Pattern p = import_text(plated_after_a_fixation(16, 12), "fixation.k").pattern;
  const knit_graph::Graph g = knit_graph::build(p);
  const layout::Layout laid = layout::lay_out(p);
  int over = 0;
  for (std::size_t i = 0; i < g.loops.size(); ++i) {
    const auto& k = g.loops[i];
    if (k.course < 2 || k.parents.empty() || k.held) continue;
    const auto& mid = [](const layout::Loop& l) { return 0.5 * (l.data_points.front().x + l.data_points.back().x); };
    EXPECT_NEAR(mid(laid.loops[i]), mid(laid.loops[static_cast<std::size_t>(k.parents.front())]), 0.5 * laid.loop_width) << "loop " << i;
    ++over;
  }
  EXPECT_GT(over, 2 * 11 * 16);
  const Fabric f = compile(p, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}

TEST(KnitoutPlating, ThreeCarriersAreWarnedOfAndAPlatedPatternExportsBothCarriers) {
  const Imported three = import_text(plated(6, 4, front_bed, "1 2 3"), "three.k");
  ASSERT_EQ(three.warnings.size(), 1u);
  EXPECT_NE(three.warnings[0].find("three.k:"), std::string::npos);
  EXPECT_NE(three.warnings[0].find("24 loops are made with three or more carriers"), std::string::npos) << three.warnings[0];

  // Written back out, each plated stitch names both carriers, and reading the program
  // gives the same stitches, plated alike.
  const Pattern p = import_text(plated(10, 6, front_bed), "plated.k").pattern;
  const Exported out = export_pattern(p, profile_named("swg"));
  EXPECT_NE(out.text.find("knit - f10 1 2\n"), std::string::npos);
  Imported back;
  EXPECT_TRUE(check_program(out.text, "plated-out.k", profile_named("swg"), &back).empty());
  ASSERT_EQ(back.pattern.courses.size(), p.courses.size());
  for (std::size_t c = 0; c < p.courses.size(); ++c) EXPECT_EQ(back.pattern.courses[c].ops, p.courses[c].ops) << "course " << c + 1;
}
