// Short rows and parts of a row: a column rises where its course reaches it and keeps
// its height where a short row turns before it (layout::Layout::column_y), in patterns
// and in machine programs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "compile.hpp"
#include "knit_graph/knit_graph.hpp"
#include "knitout.hpp"
#include "layout/layout.hpp"
#include "support.hpp"

using namespace knitc;

namespace {

Pattern run(const std::string& body) {
  return runtime::run_pattern(
             "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\n" + body,
             "t.lua")
      .pattern;
}

// A wedge: plain rows, then `turns` pairs of short rows each turning one stitch sooner
// at both edges, then plain rows again.
std::string wedge(int stitches, int turns) {
  std::string s = "cast_on(" + std::to_string(stitches) + ")\nfor _ = 1, 2 do row \"k\" row \"p\" end\n";
  for (int t = 1; t <= turns; ++t) {
    const std::string held = "held " + std::to_string(t);
    for (const std::string st : {"k", "p"})
      s += "row \"" + held + ", " + st + " " + std::to_string(stitches - 2 * t) + ", " + held + "\"\n";
  }
  return s + "for _ = 1, 2 do row \"k\" row \"p\" end\n";
}

// The feet of a loop: its first data point's height.
double feet(const layout::Loop& l) { return l.data_points.front().y; }

// Needle i, front bed.
std::string n(int i) { return "f" + std::to_string(i); }

// A knitout program's start: carrier 1 casts on needles 1 to `needles` (tucks on the even
// ones leftward, the odd ones rightward), and carrier 2 comes in.
std::string two_carriers_cast_on(int needles) {
  std::string k = ";!knitout-2\n;;Carriers: 1 2\ninhook 1\n";
  for (int i = needles; i >= 1; --i)
    if (i % 2 == 0) k += "tuck - " + n(i) + " 1\n";
  for (int i = 1; i <= needles; ++i)
    if (i % 2 == 1) k += "tuck + " + n(i) + " 1\n";
  return k + "releasehook 1\ninhook 2\n";
}

}  // namespace

TEST(ShortRows, EachColumnSaysWhatItStandsOnAndWhetherTheRowReachedIt) {
  // Worked from the right edge: k2tog over the two stitches on the right, a yarn over,
  // and the two on the left left unreached.
  const auto g = knit_graph::build(run("cast_on(4)\nrow \"k2tog, yo, held 2\"\n"));
  ASSERT_EQ(g.stands_on.size(), 2u);
  EXPECT_TRUE(g.stands_on[0].empty());  // the cast-on stands on nothing
  const auto& c = g.stands_on[1];
  ASSERT_EQ(c.size(), 4u);
  for (int s : {0, 1}) {
    EXPECT_EQ(c[s].below, s);
    EXPECT_EQ(c[s].across, 1);
    EXPECT_FALSE(c[s].reached);
  }
  EXPECT_EQ(c[2].below, -1);  // the yarn over stands on nothing
  EXPECT_TRUE(c[2].reached && c[2].pulled);
  EXPECT_EQ(c[3].below, 2);  // the k2tog on the two it gathers
  EXPECT_EQ(c[3].across, 2);
  EXPECT_TRUE(c[3].reached && c[3].pulled);
  EXPECT_EQ(g.live_columns, (std::vector<int>{0, 1, 2, 3}));
}

TEST(ShortRows, AWedgeRisesWhereItIsKnittedAndNowhereElse) {
  // Ten short rows reach the middle and not the edge stitches: laid by courses, as until
  // 2026-12-07, every course stood level and the edge loops under them stretched up
  // eleven courses to the first plain row after them.
  const int stitches = 24, turns = 5;
  const Pattern p = run(wedge(stitches, turns));
  const Fabric f = compile(p, test::centrelines(false));
  const layout::Layout& l = f.layout;
  const double C = l.course_spacing;
  EXPECT_FALSE(l.column_y.empty());
  // The last row: its middle stands ten courses above its edges.
  const int last = static_cast<int>(p.courses.size());
  double edge = NAN, middle = NAN;
  for (const auto& loop : l.loops)
    if (loop.course == last) {
      if (loop.wale == 0) edge = feet(loop);
      if (loop.wale == stitches / 2) middle = feet(loop);
    }
  EXPECT_NEAR(middle - edge, 2.0 * turns * C, 1e-9);
  // No loop is pulled through one more than a course below it.
  const knit_graph::Graph g = knit_graph::build(p);
  int checked = 0;
  for (std::size_t i = 0; i < g.loops.size(); ++i) {
    if (g.loops[i].parents.size() != 1) continue;
    const double up = feet(l.loops[i]) - feet(l.loops[static_cast<std::size_t>(g.loops[i].parents.front())]);
    EXPECT_NEAR(up, C, 1e-9) << "course " << g.loops[i].course << " column " << g.loops[i].slot;
    ++checked;
  }
  EXPECT_GT(checked, stitches * 8);
  // The fabric is laid as tall as its middle: the cast-on, eight plain rows and the ten
  // short ones above it.
  EXPECT_NEAR(layout::laid_height(l), (8 + 2 * turns + 1) * C, 1e-9);
}

TEST(ShortRows, ASelvedgeTurnedBeforeEveryOtherRowStaysLevel) {
  // A machine's pass that stops one needle short every other row leaves a single column
  // behind by a course: the next row that reaches it stretches its loop up to its
  // neighbours' (as a slipped stitch), so the fabric stays level and is laid by courses.
  std::string s = "cast_on(10)\n";
  for (int r = 0; r < 10; ++r) s += "row \"k\"\nrow \"held 1, p 9\"\n";
  const Pattern p = run(s);
  const Fabric f = compile(p, test::centrelines(false));
  EXPECT_TRUE(f.layout.column_y.empty());
}

TEST(ShortRows, AnIntarsiasPartsRiseTogether) {
  // Two carriers each knit their half of the needles in passes of their own, the left
  // one tucking on the right half's first needle to join them: each row is two courses,
  // each reaching half the columns. Laid by courses the fabric stood twice as tall as
  // it is knitted, each half's loops stretched over two courses.
  const int w = 8, rows = 12;
  std::string k = two_carriers_cast_on(2 * w);
  for (int r = 0; r < rows; ++r) {
    if (r % 2 == 0) {
      for (int i = 1; i <= w; ++i) k += "knit + " + n(i) + " 1\n";
      k += "tuck + " + n(w + 1) + " 1\n";
      for (int i = w + 1; i <= 2 * w; ++i) k += "knit + " + n(i) + " 2\n";
    } else {
      for (int i = 2 * w; i > w; --i) k += "knit - " + n(i) + " 2\n";
      for (int i = w; i >= 1; --i) k += "knit - " + n(i) + " 1\n";
    }
    if (r == 0) k += "releasehook 2\n";
  }
  k += "outhook 1\nouthook 2\n";
  const Pattern p = knitout::import_text(k, "intarsia.k").pattern;
  const Fabric f = compile(p, test::centrelines(false));
  const layout::Layout& l = f.layout;
  const double C = l.course_spacing;
  // The last loop of every column, both carriers': level.
  std::vector<double> top(static_cast<std::size_t>(2 * w), -1.0);
  std::vector<int> top_course(static_cast<std::size_t>(2 * w), -1);
  for (const auto& loop : l.loops)
    if (loop.wale < 2 * w && loop.shape != layout::Template::tuck && loop.course > top_course[static_cast<std::size_t>(loop.wale)]) {
      top_course[static_cast<std::size_t>(loop.wale)] = loop.course;
      top[static_cast<std::size_t>(loop.wale)] = feet(loop);
    }
  for (int s = 0; s < 2 * w; ++s) EXPECT_NEAR(top[static_cast<std::size_t>(s)], top[0], 1e-9) << "column " << s;
  // As tall as its rows, the cast-on's and the knitted ones, not twice.
  EXPECT_LE(top[0], (rows + 2) * C + 1e-9);
  EXPECT_GE(top[0], rows * C - 1e-9);
}

TEST(ShortRows, AnIntarsiasTucksAtTheJoinClearTheLoopsTheyAreHeldWith) {
  // CMU's intarsia joins its parts so: a carrier knits its part, tucks the next part's
  // edge needle, and knits back; the other carrier later knits that needle through its
  // own loop and the tuck. The tuck's column does not rise for its course, so the tuck
  // stands as high as the loop it is held with; laid on it (0.4 d behind its legs, the
  // same feet), relaxing passed 58 of 13,000 crossings of CMU's program through, 1 once
  // its legs and feet lie further behind.
  const int w = 6, rows = 8;
  std::string k = two_carriers_cast_on(2 * w);
  for (int r = 0; r < rows; ++r) {
    for (int i = 1; i <= w; ++i) k += "knit + " + n(i) + " 1\n";
    k += "tuck - " + n(w + 1) + " 1\n";
    for (int i = w; i >= 1; --i) k += "knit - " + n(i) + " 1\n";
    for (int i = 2 * w; i > w; --i) k += "knit - " + n(i) + " 2\n";
    k += "tuck + " + n(w) + " 2\n";
    for (int i = w + 1; i <= 2 * w; ++i) k += "knit + " + n(i) + " 2\n";
    if (r == 0) k += "releasehook 2\n";
  }
  k += "outhook 1\nouthook 2\n";
  const Pattern p = knitout::import_text(k, "intarsia.k").pattern;
  const Fabric laid = compile(p, test::centrelines(false));
  const layout::Layout& l = laid.layout;
  ASSERT_FALSE(l.column_y.empty());
  // Each tuck at the join lies at the same height as the loop it is held with (the loop
  // below it in its column, the other carrier's), and far enough behind it for their
  // cores (about half the diameter) to clear, feet and all.
  const double d = p.yarns.front().diameter;
  int tucks = 0;
  for (const auto& tuck : l.loops) {
    // Not the cast-on's tucks, nor the first join's, held with one of them.
    if (tuck.shape != layout::Template::tuck || tuck.course < 3) continue;
    const layout::Loop* held = nullptr;
    for (const auto& loop : l.loops)
      if (loop.wale == tuck.wale && loop.course < tuck.course && loop.shape != layout::Template::tuck &&
          (!held || loop.course > held->course))
        held = &loop;
    ASSERT_NE(held, nullptr);
    ASSERT_NEAR(feet(*held), feet(tuck), 1e-9) << "course " << tuck.course;
    for (std::size_t i = 0; i < tuck.data_points.size(); ++i)
      EXPECT_GE(std::abs(tuck.data_points[i].z - held->data_points[i].z), 0.75 * d) << "course " << tuck.course << " point " << i;
    ++tucks;
  }
  EXPECT_EQ(tucks, 2 * rows - 1);
  // Relaxed, no yarn passes through another.
  const Fabric f = compile(p, test::centrelines(true));
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}
