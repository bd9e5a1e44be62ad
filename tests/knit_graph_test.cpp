// The knit graph: parents, yarn order and the needle's live stitches for each kind of
// stitch.
#include <gtest/gtest.h>

#include "knit_graph/knit_graph.hpp"
#include "support.hpp"

namespace knitc {
namespace {

Pattern run(const std::string& body, bool flat = false) {
  return runtime::run_pattern(std::string("pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, ") +
                                  "B = { diameter = 1 } }" + (flat ? ", knitting = \"flat\"" : "") + " }\n" + body,
                              "t.lua")
      .pattern;
}

// The loop at (course, position).
const knit_graph::Loop& at(const knit_graph::Graph& g, int course, int position) {
  return g.loops[g.course_first[course] + position];
}

TEST(KnitGraph, JerseyLoopsArePulledThroughTheLoopBelow) {
  const auto g = knit_graph::build(run("cast_on(3)\nrows(2, \"k\")\n"));
  ASSERT_EQ(g.loops.size(), 9u);
  ASSERT_EQ(g.course_first.size(), 4u + 0u);  // cast-on, two courses, the end
  for (int c = 1; c <= 2; ++c) {
    for (int w = 0; w < 3; ++w) {
      const auto& l = at(g, c, w);
      EXPECT_EQ(l.course, c);
      EXPECT_EQ(l.position, w);
      ASSERT_EQ(l.parents.size(), 1u);
      EXPECT_EQ(l.parents[0], g.course_first[c - 1] + w);
    }
  }
  // In the round every row is worked from the right edge: the order along the yarn runs
  // right to left in each course and continues course after course.
  EXPECT_EQ(at(g, 0, 2).order, 0);
  EXPECT_EQ(at(g, 0, 0).order, 2);
  EXPECT_EQ(at(g, 1, 2).order, 3);
  EXPECT_EQ(at(g, 1, 0).order, 5);
  EXPECT_EQ(at(g, 2, 2).order, 6);
  EXPECT_EQ(g.live.size(), 3u);
}

TEST(KnitGraph, FlatWrongSideRowsRunLeftToRight) {
  const auto g = knit_graph::build(run("cast_on(3)\nrows(2, \"k\")\n", true));
  EXPECT_EQ(at(g, 1, 2).order, 3);  // right side: from the right edge
  EXPECT_EQ(at(g, 2, 0).order, 6);  // wrong side: from the left edge, as the yarn turns
  EXPECT_EQ(at(g, 2, 2).order, 8);
}

TEST(KnitGraph, DecreasesGatherAndYarnOversHaveNoParent) {
  // Face view of "k1, yo, k2tog, k1" worked from the right edge: k, k2tog, yo, k.
  const auto g = knit_graph::build(run("cast_on(4)\nrow \"k1, yo, k2tog, k1\"\n"));
  ASSERT_EQ(g.course_first[2] - g.course_first[1], 4);
  EXPECT_EQ(stitch(at(g, 1, 1).stitch).name, "k2tog");
  EXPECT_EQ(at(g, 1, 1).parents, (std::vector<int>{1, 2}));
  EXPECT_EQ(stitch(at(g, 1, 2).stitch).name, "yo");
  EXPECT_TRUE(at(g, 1, 2).parents.empty());
  EXPECT_EQ(at(g, 1, 3).parents, (std::vector<int>{3}));
}

TEST(KnitGraph, TucksAreHeldAndKnittedOffWithTheOldLoop) {
  const auto g = knit_graph::build(run("cast_on(2)\nrow \"tuck, k\"\nrow \"k\"\n"));
  // Face: k, tuck. The tuck loop is held; the next loop above goes through both.
  const auto& tuck = at(g, 1, 1);
  EXPECT_TRUE(tuck.held);
  EXPECT_TRUE(tuck.parents.empty());
  const int tuck_index = g.course_first[1] + 1;
  EXPECT_EQ(at(g, 2, 1).parents, (std::vector<int>{1, tuck_index}));
}

TEST(KnitGraph, SlippedStitchesMakeNoLoopAndFloat) {
  const auto g = knit_graph::build(run("cast_on(3)\nrow \"k1, sl1 wyif, k1\"\nrow \"k\"\n"));
  EXPECT_EQ(g.course_first[2] - g.course_first[1], 2);  // two loops made, one slipped
  ASSERT_EQ(g.floats.size(), 1u);
  EXPECT_EQ(g.floats[0].first, 1);
  EXPECT_TRUE(g.floats[0].in_front);
  // The loop above the slipped stitch is pulled through the cast-on loop, two courses down.
  EXPECT_EQ(at(g, 2, 1).parents, (std::vector<int>{1}));
}

TEST(KnitGraph, CablesCrossTheirParents) {
  // C4F: the right pair is held in front and worked last, so it lands on the left.
  const auto g = knit_graph::build(run("cast_on(4)\nrow \"C4F\"\n"));
  EXPECT_EQ(at(g, 1, 0).parents, (std::vector<int>{2}));
  EXPECT_EQ(at(g, 1, 1).parents, (std::vector<int>{3}));
  EXPECT_EQ(at(g, 1, 2).parents, (std::vector<int>{0}));
  EXPECT_EQ(at(g, 1, 3).parents, (std::vector<int>{1}));
  // T3B: one purl held in back; the knit pair moves right.
  const auto t = knit_graph::build(run("cast_on(3)\nrow \"T3B\"\n"));
  EXPECT_EQ(at(t, 1, 0).parents, (std::vector<int>{2}));
  EXPECT_EQ(at(t, 1, 1).parents, (std::vector<int>{0}));
  EXPECT_EQ(at(t, 1, 2).parents, (std::vector<int>{1}));
}

TEST(KnitGraph, EachYarnCountsItsOwnOrder) {
  const auto g = knit_graph::build(run("cast_on(2)\nrow \"k\"\nyarn \"B\"\nrow \"k\"\n"));
  EXPECT_EQ(at(g, 2, 1).yarn, 1);
  EXPECT_EQ(at(g, 2, 1).order, 0);  // B's first loop
  EXPECT_EQ(at(g, 2, 0).order, 1);
}

TEST(KnitGraph, ATuckStackIsKnittedOffTogether) {
  // Two tucks on the middle needle, then a knit row: the loop above takes the cast-on loop
  // and both held loops, oldest first, and the needle positions never move.
  const auto g = knit_graph::build(run("cast_on(3)\nrow \"k1, tuck1, k1\"\nrow \"k1, tuck1, k1\"\nrow \"k\"\n"));
  const int first_tuck = g.course_first[1] + 1, second_tuck = g.course_first[2] + 1;
  EXPECT_TRUE(g.loops[first_tuck].held);
  EXPECT_TRUE(g.loops[second_tuck].held);
  EXPECT_EQ(g.loops[second_tuck].slot, 1);
  EXPECT_EQ(at(g, 3, 1).parents, (std::vector<int>{1, first_tuck, second_tuck}));
  EXPECT_EQ(at(g, 3, 0).parents, (std::vector<int>{g.course_first[2]}));
  EXPECT_EQ(g.needle, (std::vector<int>{3, 3, 3, 3}));
}

TEST(KnitGraph, AStripeChangeStartsTheNewYarnOnTheOldLoops) {
  // Flat: two rows in A, two in B. B's first loops are pulled through A's last, and each
  // yarn counts its own order from the edge its row starts at.
  const auto g = knit_graph::build(run("cast_on(3)\nrows(2, \"k\")\nyarn \"B\"\nrows(2, \"k\")\n", true));
  for (int w = 0; w < 3; ++w) {
    EXPECT_EQ(at(g, 3, w).yarn, 1);
    EXPECT_EQ(at(g, 3, w).parents, (std::vector<int>{g.course_first[2] + w}));
    EXPECT_EQ(at(g, 2, w).yarn, 0);
  }
  EXPECT_EQ(at(g, 3, 2).order, 0);  // row 3 is a right-side row: from the right edge
  EXPECT_EQ(at(g, 4, 0).order, 3);  // row 4 turns at the left edge
  // The cast-on ends at the right edge, where row 1 starts.
  EXPECT_EQ(at(g, 0, 0).order, 0);
  EXPECT_EQ(at(g, 1, 2).order, 3);
}

// A drop lets the stitch off and its wale unravels down to the yarn over it grew from,
// that too: every loop of the run a rung, with no parents and no children left.
TEST(KnitGraph, ADroppedStitchUnravelsItsWaleToTheYarnOver) {
  const auto g = knit_graph::build(run("cast_on(4)\nrow \"k2, yo, k2\"\nrows(3, \"k\")\nrow \"k2, drop, k2\"\nrow \"k\"\n"));
  EXPECT_EQ(g.needle, (std::vector<int>{4, 5, 5, 5, 5, 4, 4}));
  for (int c = 1; c <= 4; ++c) {
    EXPECT_TRUE(at(g, c, 2).unravelled) << "course " << c;
    EXPECT_TRUE(at(g, c, 2).parents.empty()) << "course " << c;
    EXPECT_FALSE(at(g, c, 1).unravelled);
    EXPECT_FALSE(at(g, c, 3).unravelled);
  }
  EXPECT_EQ(g.course_first[6] - g.course_first[5], 4);  // the drop makes no loop
  for (int w = 0; w < 4; ++w) {  // nothing above is pulled through the ladder
    for (int p : at(g, 5, w).parents) EXPECT_FALSE(g.loops[static_cast<std::size_t>(p)].unravelled);
    for (int p : at(g, 6, w).parents) EXPECT_FALSE(g.loops[static_cast<std::size_t>(p)].unravelled);
  }
  EXPECT_FALSE(at(g, 0, 2).unravelled);  // the run stops at the yarn over
}

// A wale that runs down through a decrease, an increase or a tuck cannot unravel as one:
// the row that drops it is refused, naming both rows.
TEST(KnitGraph, ADropThatCannotUnravelIsRefusedAtItsRow) {
  struct Case {
    const char* rows;
    const char* says;
  } cases[] = {
      {"row \"k2tog, k1\"\nrow \"drop, k1\"\n", "row 2 drops a stitch whose wale would unravel down through 2 stitches worked together at row 1"},
      {"row \"k1, kfb, k1\"\nrow \"k1, drop, k2\"\n", "row 2 drops a stitch whose wale would unravel into an increase worked at row 1"},
      {"row \"k1, tuck, k1\"\nrow \"k1, drop, k1\"\n", "row 2 drops a stitch holding a tuck"},
  };
  for (const Case& c : cases) {
    const Pattern p = run(std::string("cast_on(3)\n") + c.rows);
    try {
      knit_graph::build(p);
      ADD_FAILURE() << "no error for " << c.rows;
    } catch (const knit_graph::RowError& e) {
      EXPECT_EQ(e.course, 2);
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

TEST(KnitGraph, ACourseThatDoesNotFitTheNeedleIsRefused) {
  Pattern p = run("cast_on(3)\nrow \"k\"\n");
  p.courses[0].ops.pop_back();
  EXPECT_THROW(knit_graph::build(p), std::invalid_argument);
}

}  // namespace
}  // namespace knitc

namespace knitc {
namespace {

// A bobble (MB: five loops in one stitch, three rows more turned over them, gathered)
// works one stitch and leaves one; its rows hang each through the one below, the gather
// through the last, and along the yarn each row turns back on the one before.
TEST(KnitGraph, ABobbleWorksRowsOfLoopsInOneStitchTurningAndGathersThem) {
  const auto g = knit_graph::build(run("cast_on(3)\nrow \"p1, MB, p1\"\nrow \"k\"\n", true));
  ASSERT_EQ(g.bobbles.size(), 1u);
  const knit_graph::Bobble& b = g.bobbles.front();
  EXPECT_EQ(b.loops, 5);
  EXPECT_EQ(b.rows, 4);
  EXPECT_EQ(g.needle, (std::vector<int>{3, 3, 3}));
  EXPECT_EQ(g.course_first[2] - g.course_first[1], 2 + 5 * 4 + 1);
  const int base = 1;  // the cast-on's middle loop
  auto loop = [&](int i) { return g.loops[static_cast<std::size_t>(i)]; };
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(loop(b.first + k).parents, std::vector<int>{base}) << "row 0 lane " << k;
    for (int r = 1; r < 4; ++r) EXPECT_EQ(loop(b.first + r * 5 + k).parents, std::vector<int>{b.first + (r - 1) * 5 + k});
  }
  EXPECT_EQ(loop(b.gathered()).parents, (std::vector<int>{b.first + 15, b.first + 16, b.first + 17, b.first + 18, b.first + 19}));
  // Worked right to left on the right side: row 0 from lane 4, row 1 back from lane 0,
  // and so on; then the gather; then the stitch to its left.
  std::vector<int> along;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 5; ++k) along.push_back(b.first + r * 5 + (r % 2 == 0 ? 4 - k : k));
  along.push_back(b.gathered());
  for (std::size_t j = 1; j < along.size(); ++j)
    EXPECT_EQ(loop(along[j]).order, loop(along[j - 1]).order + 1) << "step " << j;
  EXPECT_EQ(loop(b.gathered()).slot, 1);
  EXPECT_EQ(loop(b.first + 7).slot, 1);  // every loop of it in its stitch's column
}

// A bobble's size follows its working in a glossary; on a wrong-side row it is refused.
TEST(KnitGraph, ABobbleTakesItsSizeFromItsWorking) {
  const auto g = knit_graph::build(
      run("stitch(\"MB\", \"[k1, p1, k1, p1], turn; K4, turn; P4, pass 2nd, 3rd and 4th st over 1st\")\ncast_on(3)\nrow \"p1, MB, p1\"\n", true));
  ASSERT_EQ(g.bobbles.size(), 1u);
  EXPECT_EQ(g.bobbles.front().loops, 4);
  EXPECT_EQ(g.bobbles.front().rows, 3);
  EXPECT_THROW(run("cast_on(3)\nrow \"k\"\nrow \"k1, MB, k1\"\n", true), runtime::PatternError);
}

}  // namespace
}  // namespace knitc
