// The work (runtime/language/work.hpp): the knitting's state without Lua, and the verbs
// all or nothing through it.
#include <gtest/gtest.h>

#include "language/work.hpp"
#include "runtime.hpp"

namespace knitc {
namespace {

using language::Work;

Pattern declared(Knitting knitting) {
  Pattern p;
  p.name = "w";
  p.knitting = knitting;
  p.yarns.push_back({"A", 1.0, "#d9c8a9"});
  return p;
}

language::RowText parsed(const std::string& text) {
  return std::get<language::RowText>(language::parse_row(text, std::vector<std::string>{"A"}));
}

TEST(Work, KeepsTheNeedleAndTheSides) {
  Work w(declared(Knitting::flat), {});
  EXPECT_EQ(w.no_live_stitches(), "no live stitches; call cast_on(n) first");
  ASSERT_FALSE(w.cast_on(8, 0, 3));
  EXPECT_EQ(w.cast_on(8, 0, 4), "cast_on was already called at line 3");
  EXPECT_FALSE(w.work_text(parsed("k2tog"), "k2tog", {"t.lua", 5}));
  EXPECT_EQ(w.live(), 4);
  EXPECT_EQ(w.side_of(1), Side::right);
  EXPECT_EQ(w.side_of(2), Side::wrong);
  EXPECT_EQ(w.pattern().courses.back().where.line, 5);
  // A row that does not fit changes nothing.
  const auto before = w.pattern();
  EXPECT_TRUE(w.work_text(parsed("k3"), "k3", {"t.lua", 6}).has_value());
  EXPECT_EQ(w.pattern(), before);
  EXPECT_EQ(w.live(), 4);
  EXPECT_FALSE(w.bind_off(7));
  EXPECT_EQ(w.no_live_stitches(), "no live stitches: all were bound off at line 7");
}

TEST(Work, AFirstRowFromTheWrongSideTurnsTheSides) {
  Work flat(declared(Knitting::flat), {});
  ASSERT_FALSE(flat.start_on_wrong_side());
  EXPECT_EQ(flat.side_of(1), Side::wrong);
  EXPECT_EQ(flat.side_of(2), Side::right);
  Work round(declared(Knitting::round), {});
  ASSERT_FALSE(round.start_on_wrong_side());
  EXPECT_EQ(round.side_of(1), Side::right);
  ASSERT_FALSE(flat.cast_on(4, 0, 1));
  ASSERT_FALSE(flat.work_text(parsed("p"), "p", {"t.lua", 2}));
  EXPECT_TRUE(flat.start_on_wrong_side().has_value());  // only before the first row
}

TEST(Work, TheLimitsAreChecked) {
  Work w(declared(Knitting::round), {10, 20});
  ASSERT_FALSE(w.cast_on(8, 0, 1));
  EXPECT_EQ(w.work_text(parsed("m1, k"), "m1, k", {"t.lua", 2}), "row 1 leaves 16 stitches; at most 10 fit on a needle");
  EXPECT_TRUE(w.pattern().courses.empty());
  Work x(declared(Knitting::round), {10, 25});  // the cast-on's 8 loops count
  ASSERT_FALSE(x.cast_on(8, 0, 1));
  EXPECT_FALSE(x.work_text(parsed("k"), "k", {"t.lua", 2}));
  EXPECT_FALSE(x.work_text(parsed("k"), "k", {"t.lua", 3}));
  EXPECT_EQ(x.work_text(parsed("k"), "k", {"t.lua", 4}), "the fabric would have more than 25 loops; knit a smaller piece");
  EXPECT_EQ(x.pattern().courses.size(), 2u);
}

TEST(Work, AMarkPutsEverythingBack) {
  Work w(declared(Knitting::flat), {});
  ASSERT_FALSE(w.cast_on(6, 0, 1));
  ASSERT_FALSE(w.work_text(parsed("k1, p1"), "k1, p1", {"t.lua", 2}));
  const Work::Mark mark = w.mark();
  const Pattern before = w.pattern();
  const int live = w.live();
  ASSERT_FALSE(w.work_text(parsed("k2tog"), "k2tog", {"t.lua", 3}));
  w.change_yarn(0);
  ASSERT_FALSE(w.bind_off(4));
  w.restore(mark);
  EXPECT_EQ(w.pattern(), before);
  EXPECT_EQ(w.live(), live);
  EXPECT_EQ(w.next_row(), 2);
  EXPECT_EQ(w.bind_off_line(), 0);
  // "Work the stitches as they appear" still reads the faces the mark kept.
  ASSERT_FALSE(w.work_text(parsed("knit the knit sts and purl the purl sts"), "", {"t.lua", 5}));
}

// pcall(rows, 5, "k2tog") fails on row 4: rows 1 to 3 used to stay in the fabric.
TEST(Work, AVerbThatFailsLeavesNothing) {
  const std::string header =
      "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\ncast_on(8)\n";
  const auto p = runtime::run_pattern(header +
                                          "assert(not pcall(rows, 5, \"k2tog\"))\n"
                                          "assert(live() == 8 and row_number() == 1)\n"
                                          "assert(not pcall(chart, [[\n| |\n| | |\n]]))\n"
                                          "assert(row_number() == 1)\n"
                                          "assert(not pcall(knitspeak, \"Row 1: k\\nRow 2: k2tog\\nRow 3: k5\\n\"))\n"
                                          "assert(row_number() == 1)\n"
                                          "assert(not pcall(legend, { [\"#\"] = \"p\", [\"$\"] = \"frobnicate\" }))\n"
                                          "row \"k\"\n",
                                      "t.lua")
                     .pattern;
  EXPECT_EQ(p.courses.size(), 1u);
  EXPECT_EQ(produced(p.courses[0]), 8);
}

}  // namespace
}  // namespace knitc
