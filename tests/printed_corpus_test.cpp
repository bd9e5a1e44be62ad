// Printed patterns gathered from public pages (tests/corpus/raw, sources in
// tests/corpus/SOURCES.md), each read as `knitc build pattern.txt` reads it: no Lua, the
// cast-on from what the text states. Those knitc reads are checked row by row against the
// stitch counts the source states or counts worked by hand; those it cannot read yet, or
// that are wrong as printed, must say so at their line.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compile.hpp"
#include "support.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

fs::path raw(const std::string& name) { return fs::path(KNITC_SOURCE_DIR) / "tests/corpus/raw" / (name + ".txt"); }

std::vector<int> counts(const Pattern& p) {
  std::vector<int> out;
  for (const Course& c : p.courses) out.push_back(produced(c));
  return out;
}

std::vector<int> repeated(int n, int value) { return std::vector<int>(static_cast<std::size_t>(n), value); }


struct Read {
  int cast_on;
  std::vector<int> counts;  // live stitches after each row
  std::optional<int> cast_on_option = std::nullopt;  // --cast-on, where the text states none knitc can find
};

// What knitc reads, with the live stitches after each row. The counts are the source's
// where it states them (its cast-on, "(33 sts)"), else worked by hand: each of these is a
// balanced pattern (every yarn over against a decrease) but for from_1981, whose row 1
// makes 3 of every 2 and row 2 takes them back.
const std::map<std::string, Read> reads = {
    {"de_knittingandsoon_grape_socks", {24, repeated(6, 24)}},  // "a multiple of 4": 24, the smallest swatch
    {"gl_mb_cable_cowl_rounds", {56, repeated(9, 56)}},  // "Cast on 56"; its MB (4 loops, 3 rows) read from its glossary
    {"gl_diannejones_cabled_firefly", {31, repeated(48, 31)}},  // 10 + 1; rows 1-24, then "Repeat rows 1-24"
    {"gl_ribbing_with_mock_cable", {30, repeated(8, 30)}},      // 7 + 2
    {"gl_theweeklystitch_wheat_ear_cable", {32, repeated(4, 32)}},  // 10 + 2
    {"nordic_drops_150_40_double_moss", {24, repeated(8, 24)}},  // rows 1-4, then "Repeat row 1 to 4"
    {"nordic_estonian_crawling_vines", {32, repeated(12, 32)}},  // 9 + 5
    {"nordic_estonian_something_from_1981", {24, {36, 24, 24, 24}}},
    {"nordic_novita_reinforced_heel_stitch", {24, repeated(2, 24)}},
    {"sm_garland", {14, repeated(32, 14)}},       // "a cast-on count of 14"; rows 1-16 twice
    {"sm_stream_bed_lace", {31, repeated(12, 31)}},  // "a cast-on count of 31"
    {"uk_ceeceescrafts_twin_leaf_headband", {23, repeated(6, 23)}},  // "cast on 23"; row 4 is "every following WS row"
    {"uk_double_moss_stitch", {25, repeated(4, 25)}},  // 2 + 1
    {"uk_jemarrowsmith_mini_horseshoe_lace", {37, repeated(8, 37)}},  // "worked over 37 stitches"
    {"uk_jemarrowsmith_zig_zag_lace", {40, repeated(24, 40)}},        // "worked over 40 stitches"
    {"uk_jostorie_twisted_cable", {44, repeated(24, 44)}},            // "Cast on 44sts"; WS rows from row 2
    {"uk_savingmummyspennies_moss_stitch", {24, repeated(2, 24)}},
    {"us_kniteditor_alternating_leaf", {25, repeated(16, 25), 25}},  // "(18+3=21+4=25) 25": border, 12 rows, border
    {"us_theweeklystitch_2023_08_cable_rib", {24, repeated(6, 24)}},  // 7 + 3
    {"us_trishknits_braided_scarf", {35, repeated(8, 35)}},            // "Cast on 35"; crosses in brackets
    {"vintage_begin_to_knit_pattern2", {34, repeated(4, 34)}},  // "Cast on 34"; row 3's last repeat ends "Y O, K 2"
    {"vintage_spool_learnhow_k2p2_ridges", {24, repeated(8, 24)}},  // "an even number", knit 2, purl 2 across
    {"vintage_spool98_cable_stitch", {30, repeated(8, 30)}},  // "Cast on 30 sts."; row 8's cable crossed from the back
};

// What knitc says of the rest, at their line: what it cannot read yet, and sources wrong
// as printed (each checked by hand against the text).
const std::map<std::string, std::string> refused = {
    // Wrong as printed.
    {"blog_wendyteaches_linen_stitch", ":16: row 2 \"p1, * p1, sl 1 wyib. Repeat from *, end p1\": the *repeat of 2"},  // R1 2n+1, R2 2n+2
    {"us_aroundnround_cats_paw_scarf", ":19: row 3 "},   // "K2tbl" where k2tog tbl is meant: row 1 makes 3 more
    {"us_kaitlins_reversible_cable_scarf", ":14: row 1 \"* K2,P2* 11 times,P1, Slip 1 with yarn in front\" uses 46"},  // cast on 24
    {"vintage_fireside_slippers_rib", ":15: row 2 "},    // 4 + 5n + 4 does not make row 1's 4 + 5n + 6
    {"us_walker_open_bobble_ocr", ":24: repeats row 1"},  // OCR: "Rows I, 3, and 5"
    // "BO to last 10 sts, k3, ..." counts the stitch left on the needle after the bind-off
    // as one more (11); knitc binds off all but the last 10 there (a counted "BO 3 sts"
    // keeps it). The fringe unravels its dropped stitches through the rows of p2tog
    // and then repeats rows 1-2 on the one stitch left.
    {"sm_loop_edging", ":13: row 4 of the text says it leaves 11 sts but its stitches leave 10"},
    {"sm_two_pretty_fringes", ":13: the repeat of row 1 of the text is printed as a right-side row"},
    // Stitches knitc has no topology for yet: clusters, stitches worked into one.
    {"sm_nasturtium_edging_v2", "unknown stitch '1-to-5 inc'"},
    {"sm_railroad_tracks", ":11: row 2 "},  // "bunny ears back dec" on row 3; the stated multiple is row 2's count
    {"gl_knitcharts_cable_3from3", "uses '3from3', which line 17 defines as"},
    {"gl_farfalle_butterfly_stitch", ":17: row 2 "},  // the butterfly lifts the floats (row 9)
    {"us_bobble_washcloth_selvedge", "\"in next stitch\" after a group"},
    {"us_purl_twist_knot_rounds", "unknown stitch 'p2tog and leave on needle'"},
    {"us_framed_cross_stitch_cable", "unknown stitch 'seed 4'"},
    {"us_knittingfool_table_1263", ":1: the knitspeak text has no rows"},  // a table, and a cluster in words
    // Crosses of ribbed stitches.
    {"us_reversible_cable_scarf_craftzine", "unknown stitch 'slip 8 sts onto cable needle'"},
    // Ambiguous, as knitc refuses to guess.
    {"uk_knitforvictory_ladder_scarf", "'inc' could mean kfb, m1 or yo"},
    {"uk_elleyarns_zig_zags", "'wyif' on its own goes with no stitch"},
    // Markers the rows work to, a border named in a note, the last repeat ended otherwise.
    {"gl_whelk_slip_stitch", ":29: row 1 of the text is printed as a right-side row"},  // "K to marker"
    {"us_moss_parallelograms_border", "uses 'B', which line 14 defines as \"Border Stitches\""},
    {"vintage_baby_lacey_shawl_centre", ":20: row 5 "},  // "ending last rep. sl.1, k.1, p.s.s.o."
    {"de_gruendl_structure_pattern", ":16: row 1 of the text is printed as a right-side row"},  // parts worked in turn
    // Prose.
    {"vintage_fancywork_block_lace", "unknown stitch 'Slip first stitch'"},
    {"vintage_lambert_cable_knitting", ":1: the knitspeak text has no rows"},
    {"vintage_lambert_willow_pattern", ":1: the knitspeak text has no rows"},
};

TEST(PrintedCorpus, EveryFileIsReadOrRefusedAtItsLine) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(KNITC_SOURCE_DIR) / "tests/corpus/raw")) {
    const std::string name = entry.path().stem().string();
    ++files;
    SCOPED_TRACE(name);
    const auto read = reads.find(name);
    const auto refusal = refused.find(name);
    ASSERT_TRUE((read != reads.end()) != (refusal != refused.end())) << "list it once, as read or as refused";
    runtime::PrintedOptions options;
    if (read != reads.end()) options.cast_on = read->second.cast_on_option;
    try {
      const auto r = runtime::run_printed_file(entry.path().string(), options);
      ASSERT_NE(read, reads.end()) << "now read: move it to the patterns knitc reads, with its counts";
      EXPECT_EQ(r.pattern.cast_on, read->second.cast_on);
      EXPECT_EQ(counts(r.pattern), read->second.counts);
    } catch (const runtime::PatternError& e) {
      ASSERT_NE(refusal, refused.end()) << e.what();
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(entry.path().string() + ":", 0), 0u) << message;  // file:line first
      EXPECT_NE(message.find(refusal->second), std::string::npos) << message;
    }
  }
  EXPECT_EQ(files, static_cast<int>(reads.size() + refused.size()));
  EXPECT_GE(reads.size(), 20u);
}

// Every pattern read is laid out and traced to the end: each stitch has its geometry.
TEST(PrintedCorpus, EveryPatternReadHasItsGeometry) {
  CompileOptions centrelines;
  centrelines.view = View::centreline;
  centrelines.relax = false;
  for (const auto& [name, read] : reads) {
    SCOPED_TRACE(name);
    runtime::PrintedOptions options;
    options.cast_on = read.cast_on_option;
    const auto r = runtime::run_printed_file(raw(name).string(), options);
    EXPECT_FALSE(compile(r.pattern, centrelines).pieces.empty());
  }
}

// The sources listed for every file.
TEST(PrintedCorpus, EveryFileHasItsSource) {
  const std::string sources = test::read_text(fs::path(KNITC_SOURCE_DIR) / "tests/corpus/SOURCES.md");
  for (const auto& entry : fs::directory_iterator(fs::path(KNITC_SOURCE_DIR) / "tests/corpus/raw")) {
    const std::string name = entry.path().stem().string();
    EXPECT_NE(sources.find(name), std::string::npos) << name;
    const std::string text = test::read_text(entry.path());
    EXPECT_NE(text.find("\n# Source: "), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace knitc
