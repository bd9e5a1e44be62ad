// The pattern language: written instructions, charts and plain Lua say the same courses;
// rows are worked as a knitter works them (right-side rows from the right, wrong-side
// rows seen from the back); charts are drawn as the face looks.
#include <gtest/gtest.h>

#include "support.hpp"
#include "language/chart.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

Pattern run(const std::string& body, bool flat = false) {
  const std::string header = std::string("pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, ") +
                             "yarns = { A = { diameter = 1.2 }, B = { weight = \"dk\", color = \"#112233\" } }" +
                             (flat ? ", knitting = \"flat\"" : "") + " }\n";
  return runtime::run_pattern(header + body, "t.lua").pattern;
}

// A course's stitches in face order, by name.
std::string face(const Course& c) {
  std::string out;
  for (const Op& op : c.ops) out += (out.empty() ? "" : " ") + std::string(stitch(op.stitch).name);
  return out;
}

TEST(Written, RightSideRowsAreWorkedFromTheRightEdge) {
  const Pattern p = run("cast_on(4)\nrow \"k1, p3\"\n");
  EXPECT_EQ(face(p.courses[0]), "p p p k");
  EXPECT_EQ(p.courses[0].side, Side::right);
}

TEST(Written, WrongSideStitchesShowTheirFace) {
  const Pattern p = run("cast_on(6)\nrow \"k\"\nrow \"k1, p2, k1, p2tog\"\nrow \"ssk, k3\"\n", true);
  EXPECT_EQ(face(p.courses[0]), "k k k k k k");
  // Worked from the left edge, seen from the back: k shows as p, p2tog as k2tog.
  EXPECT_EQ(face(p.courses[1]), "p k k p k2tog");
  EXPECT_EQ(p.courses[1].side, Side::wrong);
  EXPECT_EQ(face(p.courses[2]), "k k k ssk");
  EXPECT_EQ(produced(p.courses[2]), 4);
}

TEST(Written, RepeatsFillTheRow) {
  EXPECT_EQ(face(run("cast_on(12)\nrow \"k2, p2\"\n").courses[0]), "p p k k p p k k p p k k");
  EXPECT_EQ(run("cast_on(12)\nrow \"k2, p2\"\n"), run("cast_on(12)\nrow \"*k2, p2; rep from *\"\n"));
  EXPECT_EQ(run("cast_on(12)\nrow \"k2, p2\"\n"), run("cast_on(12)\nrow \"(k2, p2) x3\"\n"));
  EXPECT_EQ(run("cast_on(12)\nrow \"k2, p2\"\n"), run("cast_on(12)\nrow \"[k2, p2] 3 times\"\n"));
  EXPECT_EQ(run("cast_on(12)\nrow \"k2, p2\"\n"), run("cast_on(12)\nrow \"*k2, p2; rep from * to end\"\n"));
  EXPECT_EQ(face(run("cast_on(10)\nrow \"*k2, p2; rep from * to last 2 sts, k2\"\n").courses[0]),
            "k k p p k k p p k k");
  EXPECT_EQ(face(run("cast_on(7)\nrow \"k1, *p1, k1; rep from *\"\n").courses[0]), "k p k p k p k");
  EXPECT_EQ(face(run("cast_on(6)\nrow \"(k1, p1) twice, k2tog.\"\n").courses[0]), "k2tog p k p k");
}

TEST(Written, CountsNamesAndYarns) {
  const Pattern p = run("cast_on(9)\nrow \"K2, yo, k2tog, sl1 wyif, SSK, C2F\"\nrow \"k1 A, k1 B\"\n");
  EXPECT_EQ(face(p.courses[0]), "C2F ssk sl wyif k2tog yo k k");
  EXPECT_EQ(produced(p.courses[0]), 8);
  ASSERT_EQ(p.courses[1].ops.size(), 8u);
  // Face order reverses working order: the first stitch worked (A) is at the right.
  EXPECT_EQ(p.courses[1].ops[7].yarn, 0);
  EXPECT_EQ(p.courses[1].ops[6].yarn, 1);
}

TEST(Written, YarnChangesMakeStripes) {
  const Pattern p = run("cast_on(4)\nrows(2, \"k\")\nyarn \"B\"\nrows(2, \"k\")\n");
  EXPECT_EQ(p.courses[1].ops[0].yarn, 0);
  EXPECT_EQ(p.courses[2].ops[0].yarn, 1);
  EXPECT_EQ(p.cast_on_yarn, 0);
}

TEST(Written, ASecondYarnIsPlatedIntoTheFirstsStitches) {
  // yarn("A", "B"): A's stitches take B with them until the yarn changes again; a
  // course{} in another yarn is not plated, and the plating goes on after it; a chart
  // cell in another yarn is not plated either.
  const Pattern p = run("cast_on(4)\nyarn(\"A\", \"B\")\nrow \"k\"\ncourse { k, k, k, k, yarn = \"B\" }\nrow \"k\"\n"
                        "legend { [\"#\"] = { \"k\", yarn = \"B\" } }\nchart [[\n  # . # .\n]]\nyarn \"A\"\nrow \"k\"\n");
  ASSERT_EQ(p.courses.size(), 5u);
  for (const Op& op : p.courses[0].ops) EXPECT_EQ(op.plated, 1);
  for (const Op& op : p.courses[1].ops) EXPECT_EQ(op.plated, -1);
  for (const Op& op : p.courses[2].ops) EXPECT_EQ(op.plated, 1);
  for (const Op& op : p.courses[3].ops) EXPECT_EQ(op.plated, op.yarn == 0 ? 1 : -1);
  for (const Op& op : p.courses[4].ops) EXPECT_EQ(op.plated, -1);
}

// The same fabrics said three ways compile to identical Patterns.
TEST(ThreeWays, TwoByTwoRib) {
  const Pattern written = run("cast_on(12)\nrows(4, \"k2, p2\")\n");
  // Worked from the right edge, k2 first: the face reads p p k k from the left.
  const Pattern charted = run("cast_on(12)\nchart { [[\n. . | |\n]], rep = 4 }\n");
  const Pattern lua = run("cast_on(12)\nfor i = 1, 4 do course { k, k, p, p, rep = 3 } end\n");
  EXPECT_EQ(written, charted);
  EXPECT_EQ(written, lua);
  EXPECT_EQ(written.courses.size(), 4u);
}

TEST(ThreeWays, SeedStitchWorkedFlat) {
  const Pattern written = run("cast_on(10)\nfor i = 1, 3 do\n  row \"k1, p1\"\n  row \"p1, k1\"\nend\n", true);
  const Pattern charted = run("cast_on(10)\nchart { [[\n| .\n. |\n]], rep = 3 }\n", true);
  const Pattern lua = run("cast_on(10)\nfor i = 1, 3 do course { k, p } course { p, k } end\n", true);
  EXPECT_EQ(written, charted);
  EXPECT_EQ(written, lua);
  // Seed: every stitch sits under its opposite.
  for (std::size_t r = 1; r < written.courses.size(); ++r) {
    for (std::size_t i = 0; i < 10; ++i) EXPECT_NE(written.courses[r].ops[i].stitch, written.courses[r - 1].ops[i].stitch);
  }
}

TEST(ThreeWays, CablePanel) {
  const Pattern written = run(
      "cast_on(16)\nfor i = 1, 2 do\n  row \"p2, C4F, p2\"\n  rows(3, \"p2, k4, p2\")\nend\n");
  const Pattern charted = run(
      "cast_on(16)\nchart { [[\n. . | | | | . .\n. . | | | | . .\n. . | | | | . .\n. . C4F---- . .\n]], rep = 2 }\n");
  const Pattern lua = run(
      "cast_on(16)\nfor i = 1, 2 do\n  course { p, p, C4F, p, p }\n  for j = 1, 3 do course { p, p, k, k, k, k, p, p } end\nend\n");
  EXPECT_EQ(written, charted);
  EXPECT_EQ(written, lua);
  EXPECT_EQ(face(written.courses[0]), "p p C4F p p p p C4F p p");
}

TEST(Charts, AreDrawnAsTheFaceLooksOnBothSides) {
  // Garter worked flat: written "k" on every row; the chart draws what the face shows.
  const Pattern written = run("cast_on(4)\nrows(4, \"k\")\n", true);
  const Pattern charted = run("cast_on(4)\nchart [[\n. . . .\n| | | |\n. . . .\n| | | |\n]]\n", true);
  EXPECT_EQ(written, charted);
}

TEST(Charts, SymbolsWithoutSpacesNamesAndLegend) {
  const Pattern a = run("cast_on(6)\nchart [[\n||..O/\n]]\n");
  const Pattern b = run("cast_on(6)\nchart [[\nk k p p yo k2tog\n]]\n");
  EXPECT_EQ(a, b);
  const Pattern colour = run("cast_on(4)\nlegend { [\"#\"] = { \"k\", yarn = \"B\" } }\nchart [[\n| # | #\n]]\n");
  EXPECT_EQ(colour.courses[0].ops[1].yarn, 1);
  EXPECT_EQ(colour.courses[0].ops[0].yarn, 0);
  const Pattern local = run("cast_on(2)\nchart { [[\n* *\n]], legend = { [\"*\"] = \"p\" } }\n");
  EXPECT_EQ(face(local.courses[0]), "p p");
}

TEST(Charts, ErrorsPointAtTheChartLine) {
  try {
    run("cast_on(4)\nchart [[\n| | | |\n| | | |\n| | ? |\n]]\n");
    FAIL();
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("t.lua:6: unknown chart symbol '?'", 0), 0u) << e.what();
  }
  try {  // text on the line of the bracket
    run("cast_on(4)\nchart [[| | | |\n| . |]]\n");
    FAIL();
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("t.lua:4: chart row 1 (row 1) is 3 stitches wide", 0), 0u) << e.what();
  }
}

TEST(Charts, StitchesWithoutAWrongSideFormStayOnRightSideRows) {
  try {
    run("cast_on(8)\nchart [[\n. . ^ . . .\n. . | | | | . .\n]]\n", true);
    FAIL();
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.lua:4: chart row 2 (row 2) is a wrong-side row: cdd has no wrong-side form in knitc; put it on a "
              "right-side (odd) row");
  }
  // A knit cross has one (worked from the back as purls crossing): charted on a
  // wrong-side row, the face shows it as charted.
  const Pattern p = run("cast_on(8)\nchart [[\n. . C4F---- . .\n. . | | | | . .\n]]\n", true);
  EXPECT_EQ(stitch(p.courses[1].ops[2].stitch).name, "C4F");
}

// Stitch markers: placed with pm, kept across rows between the same stitches, and the
// room a part of a row works to ("k to m", "rep from * to 2 sts before m, ..."). The
// rows are the whelk dishcloth's (tests/corpus/raw/gl_whelk_slip_stitch.txt), on the
// 17 stitches of its multiple of 4 + 3 less the border's difference, worked by hand:
// slipped stitches at 6 and 10 on row 1 (face view, from the left), 6 and 10 on row 2,
// 4, 8 and 12 on rows 3 and 4.
TEST(Markers, RowsWorkToTheMarkersTheRowsBeforePlaced) {
  const Pattern p = run("cast_on(17)\n"
                        "row \"K3, pm; K3, * sl 1 wyib, K3; rep from * to last 3 stitches; pm, K to end.\"\n"
                        "row \"K to marker; K3, * sl 1 wyif, K3; rep from * to marker; K to end.\"\n"
                        "row \"K to marker; K1, * sl 1 wyib, K3; rep from * to 2 stitches before marker, sl 1 wyib, K1;  K to end.\"\n"
                        "row \"K to marker; P1, sl 1 wyif, * P3, sl 1 wyif; rep from * to last stitch before marker, P1; K to end.\"\n"
                        "row \"k to m, sm, p to m, sm, k to end\"\n",
                        true);
  ASSERT_EQ(p.courses.size(), 5u);
  auto slipped = [&](std::size_t row) {
    std::vector<int> at;
    for (std::size_t i = 0; i < p.courses[row].ops.size(); ++i)
      if (stitch(p.courses[row].ops[i].stitch).family == StitchFamily::slip) at.push_back(static_cast<int>(i));
    return at;
  };
  EXPECT_EQ(slipped(0), (std::vector<int>{6, 10}));
  EXPECT_EQ(slipped(1), (std::vector<int>{6, 10}));
  EXPECT_EQ(slipped(2), (std::vector<int>{4, 8, 12}));
  EXPECT_EQ(slipped(3), (std::vector<int>{4, 8, 12}));
  EXPECT_EQ(face(p.courses[4]), "k k k p p p p p p p p p p p k k k");
}

TEST(Markers, AMarkerNotWhereTheRowSaysIsRefused) {
  auto error = [](const std::string& body) {
    try {
      run("cast_on(10)\n" + body, true);
    } catch (const runtime::PatternError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("row \"k to m, k to end\"\n"),
            "t.lua:3: row 1 \"k to m, k to end\" works to a marker, but no marker lies ahead on the needle; place one "
            "with pm on an earlier row");
  EXPECT_EQ(error("row \"k3, pm, k to end\"\nrow \"p2, sm, p to end\"\n"),
            "t.lua:4: row 2 \"p2, sm, p to end\" works 2 stitches before a marker 7 stitches on; make them agree");
  // Markers stay between the same stitches: two decreases worked before one on a
  // right-side row leave it where it was, counted from the left edge.
  EXPECT_EQ(error("row \"k5, pm, k to end\"\nrow \"p\"\nrow \"k2tog, k2tog, k to end\"\nrow \"p5, sm, p to end\"\n"),
            "no error");
}

TEST(ChartText, NumbersEachRowOnTheSideItIsReadFrom) {
  const Pattern p = run("cast_on(4)\nrow \"k2, p2\"\nrow \"k1, p1\"\nrow \"k2tog, yo, k2\"\n", true);
  EXPECT_EQ(language::chart_text(p),
            "# t: 3 rows on 4 stitches, flat; right side shown, row 1 at the bottom, each row numbered on the side it is "
            "read from\n"
            "   | | O /  3\n"
            "2  . | . |\n"
            "   . . | |  1\n");
}

TEST(ChartText, ShowsCablesAcrossTheirWidthAndYarns) {
  const Pattern p = run("cast_on(6)\nrow \"p1, C4F, p1\"\nrow \"k1 A, k1 B\"\n");
  EXPECT_EQ(language::chart_text(p),
            "# t: 2 rows on 6 stitches, in the round; right side shown, row 1 at the bottom, each row numbered on the "
            "side it is read from\n"
            "   | | | | | |  2   B A B A B A\n"
            "   . C4F---- .  1   A A A\n");
}

TEST(Checks, LongFloatsAreWarnedAbout) {
  const auto r = runtime::run_pattern(
      "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(12)\n"
      "row \"k\"\nrow \"k2, sl8 wyib, k2\"\n",
      "t.lua");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "t.lua:4: warning: row 2 slips 8 stitches in a row: a float of 40 mm, over the 25 mm that wears well; "
            "break the run of slips");
  const auto stranded = runtime::run_pattern(
      "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, B = { diameter = 1 } } }\n"
      "cast_on(16)\nrow \"k1 B, k14 A, k1 B\"\n",
      "t.lua");
  ASSERT_EQ(stranded.warnings.size(), 1u);
  EXPECT_NE(stranded.warnings[0].find("carries yarn B across 14 stitches"), std::string::npos) << stranded.warnings[0];
}

TEST(Metadata, WeightsAndSeeds) {
  const Pattern p = run("cast_on(2)\nrow \"k\"\nbind_off()\n");
  EXPECT_NEAR(p.yarns[1].diameter, 0.85 * 25.4 / 13.0, 1e-12);  // dk
  EXPECT_TRUE(p.bound_off);
  auto stitches_from = [](const std::string& seed, std::optional<std::int64_t> override) {
    runtime::RunOptions o;
    o.seed = override;
    return runtime::run_pattern("pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }" + seed +
                                    " }\ncast_on(math.random(10, 1000))\nrow \"k\"\n",
                                "t.lua", o)
        .pattern.cast_on;
  };
  EXPECT_EQ(stitches_from(", seed = 7", std::nullopt), stitches_from(", seed = 7", std::nullopt));
  EXPECT_NE(stitches_from(", seed = 7", std::nullopt), stitches_from(", seed = 8", std::nullopt));
  EXPECT_EQ(stitches_from(", seed = 7", 99), stitches_from(", seed = 8", 99));  // --seed wins
}

TEST(Reference, DocsAreGeneratedFromTheTables) {
  const std::string docs = test::read_text(std::filesystem::path(KNITC_SOURCE_DIR) / "docs/language.md");
  EXPECT_TRUE(docs == runtime::language_reference())
      << "docs/language.md is stale: run ./build/cli/knitc reference > docs/language.md";
  for (const StitchDef& s : stitch_table()) EXPECT_NE(docs.find(std::string(s.name)), std::string::npos) << s.name;
}

}  // namespace
}  // namespace knitc
