// Printed patterns (issue 8): the knitspeak block's reading of row labels, lists, repeats
// and counts; the written rows' printed forms (open repeats, psso, "knit the knit sts");
// and the knitter-written corpus in ../shared/corpus, compiled from its translation and
// from its raw text, with stitch counts worked by hand.
#include <cctype>
#include <filesystem>
#include <map>
#include <regex>

#include <gtest/gtest.h>

#include "compile.hpp"
#include "knit_graph/knit_graph.hpp"
#include "language/knitspeak.hpp"
#include "language/words.hpp"
#include "support.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

const language::Knitspeak& read_ok(const std::variant<language::Knitspeak, language::KnitspeakNote>& r) {
  if (const auto* e = std::get_if<language::KnitspeakNote>(&r)) ADD_FAILURE() << e->line << ": " << e->message;
  static const language::Knitspeak none;
  return r.index() == 0 ? std::get<language::Knitspeak>(r) : none;
}

TEST(Knitspeak, ReadsLabelsListsAndRangesInNumberOrder) {
  const auto r = language::read_knitspeak(
      "Rows 1 and 3 (WS): Purl.\n"
      "  Row 2: K1, *p1, k1; rep from *.\n"
      "- Rows 4, 6, and 8-9: Knit.\n"
      "Row 5 (RS): k2tog, yo, k1 (3 sts).\n"
      "Row 7: Purl\n",
      {});
  const auto& k = read_ok(r);
  ASSERT_EQ(k.rows.size(), 9u);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(k.rows[static_cast<std::size_t>(i)].number, i + 1);
  EXPECT_EQ(k.rows[0].text, "Purl");
  EXPECT_EQ(k.rows[0].side, Side::wrong);
  EXPECT_EQ(k.rows[1].text, "K1, *p1, k1; rep from *");
  EXPECT_EQ(k.rows[1].line, 1);
  EXPECT_EQ(k.rows[4].text, "k2tog, yo, k1");
  EXPECT_EQ(k.rows[4].stitches_after, 3);
  EXPECT_EQ(k.rows[8].text, "Knit");
  EXPECT_EQ(k.rows[8].line, 2);
  EXPECT_TRUE(k.skipped.empty());
}

// "(-3 sts)" after a row says what it took away, not what it leaves: a note, dropped, no
// stated count (the fuzzer found it read as a count of -3).
TEST(Knitspeak, ASignedCountIsANoteNotTheRowsCount) {
  const auto r = language::read_knitspeak("Row 1: k1, k2tog (-1 sts).\nRow 2: Purl.\n", {});
  const auto& k = read_ok(r);
  ASSERT_EQ(k.rows.size(), 2u);
  EXPECT_EQ(k.rows[0].text, "k1, k2tog");
  EXPECT_FALSE(k.rows[0].stitches_after.has_value());
}

TEST(Knitspeak, RowsGivenAsEarlierOnesAndRepeatsWhereTheyStand) {
  const auto r = language::read_knitspeak(
      "Rnd 1: k1, p1.\nRnd 2: p1, k1.\nRnds 3-4: Repeat rnds 1-2.\nRepeat rounds 2-3.\nRnd 5 \u2013 6: Knit.\n", {});
  const auto& k = read_ok(r);
  std::vector<std::string> texts;
  for (const auto& row : k.rows) texts.push_back(row.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"k1, p1", "p1, k1", "k1, p1", "p1, k1", "p1, k1", "k1, p1", "Knit", "Knit"}));
  EXPECT_EQ(k.rows[4].line, 3);
  EXPECT_TRUE(k.rows[4].repeat);
}

TEST(Knitspeak, SkipsHeadingsAndNotesButReadsUnnumberedRows) {
  const auto r = language::read_knitspeak("# Twisted rib\n```knitting\nNotes: worked flat.\nk2, p2 to end of round.\n```\n", {});
  const auto& k = read_ok(r);
  ASSERT_EQ(k.rows.size(), 1u);
  EXPECT_EQ(k.rows[0].number, 0);
  EXPECT_EQ(k.rows[0].text, "k2, p2 to end of round");
  ASSERT_EQ(k.skipped.size(), 2u);
  EXPECT_EQ(k.skipped[0].line, 0);
  EXPECT_EQ(k.skipped[1].line, 2);
}

TEST(Knitspeak, SaysWhatIsWrongAndWhere) {
  auto error = [](std::string_view text) {
    const auto r = language::read_knitspeak(text, {});
    const auto* e = std::get_if<language::KnitspeakNote>(&r);
    return e ? std::to_string(e->line) + ": " + e->message : std::string("no error");
  };
  EXPECT_EQ(error("Row 1: k.\nRow 1: p."), "1: row 1 is given twice");
  EXPECT_EQ(error("Row 1: k.\n\nRow 4: p."), "2: row 4 is given but row 2 never is; number the rows without a gap");
  EXPECT_EQ(error("Rows 5-6: Repeat rows 1-4."), "0: 2 rows repeat 4; give as many rows as they repeat (Rows 5-8: Repeat rows 1-4)");
  EXPECT_EQ(error("Row 2: k.\nRow 1: Repeat row 2."),
            "1: row 1 repeats row 2, which comes later or not at all; repeat rows already worked");
  EXPECT_EQ(error("Row 1:   "), "0: row 1 has no stitches after its label");
}

Pattern run(const std::string& body, const std::string& knitting = "flat") {
  return runtime::run_pattern("pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"" +
                                  knitting + "\" }\n" + body,
                              "t.lua")
      .pattern;
}

using test::names;

TEST(Written, OpenRepeatsAsKnittersPrintThem) {
  // Face view, left to right; a right-side row is worked from the right, so written
  // order reverses.
  EXPECT_EQ(names(run("cast_on(10)\nrow \"k1, (p2, k2) to 1 st before end of row, k1\"\n").courses[0]),
            (std::vector<std::string>{"k", "k", "k", "p", "p", "k", "k", "p", "p", "k"}));
  EXPECT_EQ(names(run("cast_on(8)\nrow \"k2, p2 to end\"\n").courses[0]),
            (std::vector<std::string>{"p", "p", "k", "k", "p", "p", "k", "k"}));
  EXPECT_EQ(names(run("cast_on(5)\nrow \"k1, p to last st, k1\"\n").courses[0]),
            (std::vector<std::string>{"k", "p", "p", "p", "k"}));
  EXPECT_EQ(names(run("cast_on(6)\nrow \"*K1, yo, k2tog, repeat from *.\"\n").courses[0]),
            (std::vector<std::string>{"k2tog", "yo", "k", "k2tog", "yo", "k"}));
}

TEST(Written, PassingOverAndCountsRunIntoNames) {
  EXPECT_EQ(names(run("cast_on(5)\nrow \"sl1, k2tog, psso, sl1, k1, psso\"\n").courses[0]),
            (std::vector<std::string>{"ssk", "sk2p"}));
  EXPECT_EQ(names(run("cast_on(3)\nrow \"k1tbl, p1, K1 TBL\"\n").courses[0]), (std::vector<std::string>{"k tbl", "p", "k tbl"}));
}

TEST(Written, KnitTheKnitsAndPurlThePurls) {
  const Pattern p = run("cast_on(6)\nrow \"k2, p1\"\nrow \"knit the knit sts and purl the purl sts.\"\n"
                        "row \"K the k sts and p the p sts\"\n");
  ASSERT_EQ(p.courses.size(), 3u);
  EXPECT_EQ(names(p.courses[1]), names(p.courses[0]));  // a wrong-side row: the face keeps its look
  EXPECT_EQ(names(p.courses[2]), names(p.courses[0]));
  EXPECT_EQ(p.courses[1].side, Side::wrong);
}

TEST(Knitspeak, InAScriptWorksRowsOnTheirSidesAndChecksCounts) {
  const Pattern p = run("cast_on(4)\nknitspeak [[\n  Row 1 (WS): Purl.\n  Row 2: k1, m1, k to end (5 sts).\n]]\n");
  ASSERT_EQ(p.courses.size(), 2u);
  EXPECT_EQ(p.courses[0].side, Side::wrong);  // printed (WS): the first row is a wrong-side row
  EXPECT_EQ(names(p.courses[0]), (std::vector<std::string>{"k", "k", "k", "k"}));
  EXPECT_EQ(produced(p.courses[1]), 5);
  EXPECT_EQ(p.courses[1].where.line, 5);
}

// The stitch below: the live loop drops and is held by the new loop, as a tuck is.
TEST(Stitches, KnitBelowHoldsTheDroppedLoop) {
  const Pattern p = run("cast_on(4)\nrow \"k\"\nrow \"k\"\nrow \"*k1 below, k1; rep from *\"\n", "round");
  const auto g = knit_graph::build(p);
  const auto& below = g.loops[static_cast<std::size_t>(g.course_first[3] + 3)];  // face order: the last worked first
  ASSERT_EQ(stitch(below.stitch).name, "k below");
  ASSERT_EQ(below.parents.size(), 2u);
  const auto& dropped = g.loops[static_cast<std::size_t>(below.parents[1])];
  EXPECT_TRUE(dropped.held);
  EXPECT_TRUE(dropped.parents.empty());
  EXPECT_EQ(dropped.course, 2);
  EXPECT_EQ(g.loops[static_cast<std::size_t>(below.parents[0])].course, 1);
}

TEST(Stitches, IncreasesWorkEveryNewLoopThroughTheOldOne) {
  const Pattern p = run("cast_on(2)\nrow \"kfb, ctr dbl inc\"\n", "round");
  const auto g = knit_graph::build(p);
  ASSERT_EQ(g.needle[1], 5);
  for (int i = g.course_first[1]; i < g.course_first[2]; ++i) EXPECT_EQ(g.loops[static_cast<std::size_t>(i)].parents.size(), 1u);
}

// A nupp as Stitch Maps counts it: five loops out of one stitch, gathered by the next
// row's p5tog (worked from the wrong side, it shows as k5tog on the face).
TEST(Stitches, NuppMakesFiveLoopsOfOneAndTheNextRowGathersThem) {
  const Pattern p = run("cast_on(3)\nrow \"k1, nupp, k1\"\nrow \"p1, p5tog, p1\"\n", "flat");
  const auto g = knit_graph::build(p);
  ASSERT_EQ(g.needle[1], 7);
  ASSERT_EQ(g.needle[2], 3);
  for (int i = g.course_first[1] + 1; i < g.course_first[1] + 6; ++i)
    EXPECT_EQ(g.loops[static_cast<std::size_t>(i)].parents, std::vector<int>{1});
  const auto& gathered = g.loops[static_cast<std::size_t>(g.course_first[2] + 1)];
  EXPECT_EQ(stitch(gathered.stitch).name, "k5tog");
  EXPECT_EQ(gathered.parents.size(), 5u);
}

using language::find_stitch;

// No spelling is shadowed by another stitch's: each finds its own stitch.
TEST(Stitches, EverySpellingNamesOneStitch) {
  const auto table = stitch_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto id = static_cast<StitchId>(i);
    language::for_each_spelling(id, [&](std::string_view w) { EXPECT_EQ(find_stitch(w), id) << w << " of " << table[i].name; });
  }
  EXPECT_GE(table.size(), 120u);  // the core, the printed vocabulary, the generated crosses
}

// A cross is made once, by its facts: every cable's Stitch Maps notation, worked out from
// what it does, is a spelling of that very stitch (C4F is 2/2 LC), and no two cables do
// the same thing.
TEST(Stitches, EveryCrossIsSpelledByItsNotation) {
  const auto table = stitch_table();
  int cables = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const StitchDef& s = table[i];
    if (s.family != StitchFamily::cable) {
      EXPECT_EQ(cross_notation(s), "") << s.name;
      continue;
    }
    ++cables;
    const std::string notation = cross_notation(s);
    EXPECT_EQ(find_stitch(notation), static_cast<StitchId>(i)) << notation << " should spell " << s.name;
    for (std::size_t j = i + 1; j < table.size(); ++j)
      EXPECT_NE(cross_notation(table[j]), notation) << s.name << " and " << table[j].name << " are one cross";
  }
  // Every cross of the generated range, the core's 14 among them, and the purled face of
  // each of the four kinds of knit cross (RC, LC, RT, LT) worked from the back.
  EXPECT_EQ(cables, 8 * (16 + 9) + 4 * (16 + 9));
}

// Every stitch has its words, and the words follow the facts: a chart symbol, a summary;
// a Lua name that is an identifier.
TEST(Stitches, EveryStitchHasItsWords) {
  const auto table = stitch_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const language::StitchWords& w = language::words(static_cast<StitchId>(i));
    EXPECT_FALSE(w.symbol.empty()) << table[i].name;
    EXPECT_FALSE(w.summary.empty()) << table[i].name;
    for (char c : w.identifier) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_') << table[i].name;
  }
}

TEST(Stitches, CrossesInBothNotations) {
  EXPECT_EQ(find_stitch("2/2 RC"), find_stitch("C4B"));
  EXPECT_EQ(find_stitch("1/1 lpc"), find_stitch("T2F"));
  const auto three = find_stitch("2/1/2 RPC");
  ASSERT_TRUE(three);
  EXPECT_EQ(stitch(*three).consumes, 5);
  EXPECT_EQ(stitch(*three).cable.middle, 1);
  const Pattern p = run("cast_on(5)\nrow \"2/1/2 RPC\"\n", "round");
  const auto g = knit_graph::build(p);
  // The outer pairs change places around the purled middle.
  std::vector<int> from;
  for (int i = g.course_first[1]; i < g.course_first[2]; ++i)
    from.push_back(g.loops[static_cast<std::size_t>(g.loops[static_cast<std::size_t>(i)].parents[0])].slot);
  EXPECT_EQ(from, (std::vector<int>{3, 4, 2, 0, 1}));
  EXPECT_TRUE(stitch(*find_stitch("1/1 RT")).twisted);
}

// ---- The corpus: knitter-written patterns, each in translation and as printed ----

fs::path corpus() { return test::shared_dir() / "corpus"; }

// The translation's pattern{} and cast_on lines, then the raw text as a knitspeak block.
std::string as_printed(const std::string& name) {
  const std::string dsl = test::read_text(corpus() / "dsl" / (name + ".lua"));
  std::smatch header, cast;
  std::regex_search(dsl, header, std::regex(R"(\npattern \{[^\n]*\n)"));
  std::regex_search(dsl, cast, std::regex(R"(\ncast_on\([0-9]+\)\n)"));
  return header.str().substr(1) + cast.str().substr(1) + "knitspeak [==[\n" + test::read_text(corpus() / "raw" / (name + ".txt")) +
         "]==]\n";
}

std::vector<int> counts(const Pattern& p) {
  std::vector<int> out;
  for (const Course& c : p.courses) out.push_back(produced(c));
  return out;
}

std::vector<int> repeated(int n, int value) { return std::vector<int>(static_cast<std::size_t>(n), value); }

// The two sources that are wrong as printed, and what knitc says of them.
const std::map<std::string, std::string> wrong_as_printed = {
    // The blog quotes the tank top's rib (multiples of 4) above lace rounds of 12 + 2.
    {"fiftyfifty_lace_rounds",
     "fiftyfifty_lace_rounds.lua:14: row 1 \"k2, p2 to end of round\" repeats every 4 stitches and does not fit 26 live "
     "stitches (2 left over); make the count a multiple of 4"},
    // Row 3 is printed before "Repeat rows from 1 to 2", which puts right-side row 1 on a
    // wrong-side row.
    {"sm_point_edging",
     "sm_point_edging.lua:14: the repeat of row 1 of the text is printed as a right-side row but is row 4 of the fabric, a "
     "wrong-side row; check the rows before it"},
};

TEST(Corpus, EveryPatternCompilesFromItsTranslationAndAsPrinted) {
  KNITC_NEED_SHARED(corpus());
  int patterns = 0;
  for (const auto& entry : fs::directory_iterator(corpus() / "dsl")) {
    const std::string name = entry.path().stem().string();
    ++patterns;
    SCOPED_TRACE(name);
    const Pattern dsl = runtime::run_pattern_file(entry.path().string()).pattern;
    EXPECT_NO_THROW(knit_graph::build(dsl));
    const auto wrong = wrong_as_printed.find(name);
    try {
      const auto printed = runtime::run_pattern(as_printed(name), name + ".lua");
      EXPECT_EQ(wrong, wrong_as_printed.end()) << "compiles, but the source is wrong as printed";
      const Pattern& raw = printed.pattern;
      // Laid out and traced to the end: every stitch has its geometry.
      CompileOptions centrelines;
      centrelines.view = View::centreline;
      EXPECT_FALSE(compile(raw, centrelines).pieces.empty());
      // The same stitches row by row as the translation (which works the block twice);
      // sm_vine_lace's translation starts on the right side where the source says (WS).
      ASSERT_LE(raw.courses.size(), dsl.courses.size());
      if (name == "sm_vine_lace") {
        EXPECT_EQ(raw.courses[0].side, Side::wrong);
        continue;
      }
      for (std::size_t i = 0; i < raw.courses.size(); ++i) EXPECT_TRUE(raw.courses[i] == dsl.courses[i]) << "row " << i + 1;
    } catch (const runtime::PatternError& e) {
      ASSERT_NE(wrong, wrong_as_printed.end()) << e.what();
      EXPECT_EQ(e.what(), wrong->second);
    }
  }
  EXPECT_EQ(patterns, 19);
}

// Live stitches after each row, worked by hand from the printed text.
TEST(Corpus, StitchCountsRowByRowWorkedByHand) {
  KNITC_NEED_SHARED(corpus());
  auto printed = [](const std::string& name) { return counts(runtime::run_pattern(as_printed(name), name + ".lua").pattern); };
  // The edging grows on right-side rows and shrinks back, as its stated counts say.
  EXPECT_EQ(printed("sm_edging"), (std::vector<int>{14, 14, 15, 15, 17, 17, 19, 19, 17, 17, 16, 16, 15, 15}));
  EXPECT_EQ(printed("ks_spikes"), repeated(18, 32));              // ctr dbl inc and sk2p balance
  EXPECT_EQ(printed("sm_feather_and_fan"), repeated(4, 23));      // 6 decreased, 6 yarn overs a repeat
  EXPECT_EQ(printed("ks_horseshoe_lace"), repeated(8, 21));       // k3tog against two yo
  EXPECT_EQ(printed("ks_cedar"), repeated(24, 28));               // [yo] twice between k2tog and ssk
  EXPECT_EQ(printed("sm_stockinette_brioche"), repeated(2, 24));
  EXPECT_EQ(printed("hat_diagonal_stripes"), repeated(8, 24));    // the four rows, quoted twice
  EXPECT_EQ(printed("sm_athena_sleeve"), repeated(4, 32));
  EXPECT_EQ(printed("sm_cabled_hottie"), repeated(2, 38));
  EXPECT_EQ(printed("sm_harrow_stitch"), repeated(4, 21));
  EXPECT_EQ(printed("sm_brennende_liab"), repeated(14, 24));      // rounds 1-10, then 4-7 again
  // In translation: rows 1-2 twice, then row 3's increases, 10 -> 12 a repeat, 9 -> 11 after.
  EXPECT_EQ(counts(runtime::run_pattern_file((corpus() / "dsl/sm_point_edging.lua").string()).pattern),
            (std::vector<int>{29, 29, 29, 29, 35}));
}

}  // namespace
}  // namespace knitc
