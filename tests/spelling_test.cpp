// Spellings as printed (issue 17): the one normalisation the written rows, the charts'
// legends and knitspeak read through. Each printed form must work the same stitches as its
// plain spelling; an ambiguous spelling must be refused with its candidates, never read.
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "language/knitspeak.hpp"
#include "language/spelling.hpp"
#include "support.hpp"

namespace knitc {
namespace {

using language::normalise;

Pattern run(const std::string& body) {
  return runtime::run_pattern(
             "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, B = { diameter = 1 } }, "
             "knitting = \"flat\" }\n" + body,
             "t.lua")
      .pattern;
}

std::vector<std::string> names(const Pattern& p) {
  std::vector<std::string> out;
  for (const Course& c : p.courses) {
    for (const Op& op : c.ops) out.emplace_back(stitch(op.stitch).name);
    out.emplace_back("/");
  }
  return out;
}

// The message a script stops with, or "" when it runs.
std::string error_of(const std::string& body) {
  try {
    run(body);
  } catch (const runtime::PatternError& e) {
    return e.what();
  }
  return "";
}

struct Printed {
  int cast_on;
  const char* printed;  // as a knitter typed it
  const char* plain;    // the same row in knitc's own spelling
};

TEST(Spelling, PrintedFormsWorkTheSameStitchesAsThePlainOnes) {
  const Printed rows[] = {
      {6, "K 2 tog, Y O, k 2, p 2", "k2tog, yo, k2, p2"},
      {7, "sl 1, k 2 tog, p.s.s.o., k 4", "sk2p, k4"},
      {6, "Sl. 1, K. 1, p.s.s.o., k 4.", "skp, k4"},
      {8, "p 5, sl 1, k2", "p5, sl1, k2"},
      {6, "sl1pw, sl1k, sl1p, k3", "sl1 pwise, sl1 kwise, sl1 pwise, k3"},
      {9, "sl5wyif, k2tbl, p2", "sl5 wyif, k2 tbl, p2"},
      {6, "sl 1 purlwise with yarn in front, k 1 through back loop, k 4", "sl1 wyif, k1 tbl, k4"},
      {6, "slip 1 st knitwise keeping yarn at back, knit 2 together, k3", "sl1 wyib, k2tog, k3"},
      {6, "k1, yarn forward, knit 2 together, wool round needle, k2 tog., k 1", "k1, yo, k2tog, yo, k2tog, k1"},
      {8, "K2. P2. K2. P2.", "k2, p2, k2, p2"},
      {8, "[k2, p2] \u00d7 2", "(k2, p2) x2"},
      {7, "*k2, p2; rep. from *, ending k2, p1", "*k2, p2; rep from * to last 3 sts, k2, p1"},
      {5, "K1, * p1, k1, rep from * ending with p1, k1.", "k1, *p1, k1; rep from * to last 2 sts, p1, k1"},
      {4, "k2tog\u00a0tbl, k2", "k2tog tbl, k2"},
      {6, "K\u2009TBL, SSK, K2TOG, K1", "k tbl, ssk, k2tog, k1"},
  };
  for (const Printed& r : rows) {
    SCOPED_TRACE(r.printed);
    const std::string cast = "cast_on(" + std::to_string(r.cast_on) + ")\n";
    const auto printed = names(run(cast + "row [==[" + r.printed + "]==]\n"));
    EXPECT_EQ(printed, names(run(cast + "row [==[" + r.plain + "]==]\n")));
  }
}

TEST(Spelling, NormalisingTwiceIsNormalisingOnce) {
  for (const char* t : {"K 2 tog., p.s.s.o., Y O", "sl 1 purlwise with yarn in front", "k2. P2. rep. from *, ending k1",
                        "\u2018k\u2019 \u2013 \u00d7 3\u2026", "...k2..", "k2 . . p2", "(k2, p2.) x2.", "1. 2. 3.",
                        // The written fuzzer's (2026-12-07): the bracket's "rep" dropped makes "rep *-*" a phrase.
                        "*k1; rep *-*rep(from * to l!st 4 sts, k2"}) {
    SCOPED_TRACE(t);
    const std::string once = normalise(t);
    EXPECT_EQ(normalise(once), once);
  }
  EXPECT_EQ(normalise("p.s.s.o."), "psso");
  EXPECT_EQ(normalise("\u2018k2\u2019 \u201ck2\u201d \u2014 \u00d7"), "'k2' \"k2\"   x");  // a dash between words parts nothing
  EXPECT_EQ(normalise("K2. P2."), "K2, P2");
  EXPECT_EQ(normalise("rep. from *"), "rep from *");
  EXPECT_EQ(normalise("k1; rep *-*rep(k2)"), "k1; rep from *(k2)");
  EXPECT_EQ(normalise("sl 1 purlwise with yarn in front"), "sl 1 pwise wyif");
  // Yarn ids keep their case: "k2 B" is yarn B.
  EXPECT_EQ(normalise("k2 B, k2 MC"), "k2 B, k2 MC");
}

TEST(Spelling, CrossesRunTogetherAndSpaced) {
  EXPECT_EQ(names(run("cast_on(5)\nrow \"2/1/2RPC\"\n")), names(run("cast_on(5)\nrow \"2/1/2 RPC\"\n")));
  EXPECT_EQ(names(run("cast_on(4)\nrow \"2/2RC\"\n")), names(run("cast_on(4)\nrow \"2/2 RC\"\n")));
  EXPECT_EQ(names(run("cast_on(4)\nrow \"C 4 F\"\n")), names(run("cast_on(4)\nrow \"C4F\"\n")));
}

TEST(Spelling, AmbiguousSpellingsAreRefusedWithTheirCandidates) {
  EXPECT_EQ(error_of("cast_on(4)\nrow \"k2, inc, k2\"\n"),
            "t.lua:3: row 1 \"k2, inc, k2\": 'inc' could mean kfb, m1 or yo (an increase, but the pattern does not "
            "say which); write the one the pattern means");
  EXPECT_EQ(error_of("cast_on(4)\nrow \"k1, kb, k2\"\n"),
            "t.lua:3: row 1 \"k1, kb, k2\": 'kb' could mean k tbl or k below (knit into the back of the stitch in "
            "British patterns, knit into the stitch below in Walker's and in brioche); write the one the pattern means");
  EXPECT_NE(error_of("cast_on(4)\nrow \"C4\"\n").find("'C4' could mean C4F or C4B"), std::string::npos);
  EXPECT_NE(error_of("cast_on(4)\nrow \"k1, make 1, k3\"\n").find("'make 1' could mean m1 or yo"), std::string::npos);
  // In a chart's legend too, and in knitspeak.
  EXPECT_NE(error_of("cast_on(4)\nchart { legend = { X = \"dec\" }, \"X..\" }\n").find("'dec' could mean k2tog, ssk or p2tog"),
            std::string::npos);
  EXPECT_NE(error_of("cast_on(4)\nknitspeak [[\nRow 1: k1, inc, k3.\n]]\n").find("'inc' could mean kfb, m1 or yo"),
            std::string::npos);
  // Every refused spelling in the table is refused, whatever its case and spacing.
  for (const auto& a : language::ambiguous_spellings()) {
    SCOPED_TRACE(std::string(a.written));
    const auto read = language::read_stitch(normalise(a.written));
    ASSERT_TRUE(std::holds_alternative<language::Ambiguous>(read));
    EXPECT_GE(std::get<language::Ambiguous>(read).candidates.size(), 2u);
  }
}

TEST(Spelling, TyposStillGetAHint) {
  EXPECT_NE(error_of("cast_on(4)\nrow \"k2, p2tgo\"\n").find("did you mean"), std::string::npos);
}

TEST(Spelling, VintageKnitspeakLabels) {
  const auto r = language::read_knitspeak(
      "1st row.\u2014K 2, p 2.\n2nd row (wrong side): P 2, k 2.\n3rd and 4th rows.\u2014As 1st and 2nd rows.\n"
      "Row 5. k2, p2.\nRow 6 - p2, k2.\n",
      {});
  ASSERT_EQ(r.index(), 0u) << std::get<language::KnitspeakNote>(r).message;
  const auto& rows = std::get<language::Knitspeak>(r).rows;
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0].number, 1);
  EXPECT_EQ(rows[0].text, "K 2, p 2");
  EXPECT_EQ(rows[1].side, Side::wrong);
  EXPECT_EQ(rows[2].number, 3);
  EXPECT_EQ(rows[4].text, "k2, p2");
  EXPECT_EQ(rows[5].number, 6);
}

}  // namespace
}  // namespace knitc
