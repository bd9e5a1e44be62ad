// A printed pattern as a file of its own (`knitc build pattern.txt`), and the edge
// stitches printed patterns open and close their rows with (issue 17).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

Pattern run(const std::string& header_fields, const std::string& body) {
  return runtime::run_pattern("pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = "
                              "\"flat\"" + header_fields + " }\n" + body,
                              "t.lua")
      .pattern;
}

using test::names;

// Face view, left to right. A right-side row is worked from the right edge, a
// wrong-side row from the left.
TEST(Selvedge, EdgeStitchesAreWorkedAsThePatternSays) {
  const std::string rows = "cast_on(5)\nrow \"edge st, k3, edge st\"\nrow \"sel st, p3, selvedge st\"\n";
  // garter, the default: knitted at both ends of every row, so a wrong-side row's show
  // as purls on the face (a ridge every other row).
  const Pattern garter = run("", rows);
  EXPECT_EQ(names(garter.courses[0]), (std::vector<std::string>{"k", "k", "k", "k", "k"}));
  EXPECT_EQ(names(garter.courses[1]), (std::vector<std::string>{"p", "k", "k", "k", "p"}));
  // chain: the first stitch of every row slipped, the last knitted.
  const Pattern chain = run(", selvedge = \"chain\"", rows);
  EXPECT_EQ(names(chain.courses[0]), (std::vector<std::string>{"k", "k", "k", "k", "sl wyib"}));
  EXPECT_EQ(names(chain.courses[1]), (std::vector<std::string>{"sl wyif", "k", "k", "k", "p"}));
  // knit: knitted on the right side, purled on the wrong: a knit column on the face.
  const Pattern knit = run(", selvedge = \"knit\"", rows);
  EXPECT_EQ(names(knit.courses[1]), (std::vector<std::string>{"k", "k", "k", "k", "k"}));
}

TEST(Selvedge, AnEdgeStitchInTheMiddleOfARowIsRefused) {
  try {
    run("", "cast_on(5)\nrow \"k2, edge st, k2\"\n");
    FAIL() << "no error";
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.lua:3: row 1 \"k2, edge st, k2\": an edge stitch belongs at the start or the end of a row, not in its middle");
  }
  try {
    run(", selvedge = \"slipped\"", "cast_on(5)\n");
    FAIL() << "no error";
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(std::string(e.what()), "t.lua:1: selvedge is \"slipped\"; use \"garter\", \"chain\" or \"knit\"");
  }
}

TEST(Selvedge, TheChainSelvedgeSlipsOneEdgeStitchARowAndCompiles) {
  // The slipped edge loop is held over two rows, drawn by the slip stitch's geometry.
  const std::string rows = "cast_on(6)\nrows(6, \"edge st, k4, edge st\")\n";
  const Pattern chain = run(", selvedge = \"chain\"", rows);
  CompileOptions o;
  o.view = View::centreline;
  EXPECT_FALSE(compile(chain, o).pieces.empty());
  int slipped = 0;
  for (const Course& c : chain.courses)
    for (const Op& op : c.ops) slipped += stitch(op.stitch).family == StitchFamily::slip;
  EXPECT_EQ(slipped, 6);  // one a row, at alternate edges
}

// Reversible and Celtic patterns cross on wrong-side rows: worked from the back as its
// right-side words say, a purl-background cross shows its held stitches at the other end
// and every stitch's other face.
TEST(WrongSideCrosses, APurlBackgroundCrossShowsAsItsMirrorFromTheFace) {
  const Pattern p = run("", "cast_on(8)\nrow \"p2, k4, p2\"\nrow \"k2, T3B, p1, k2\"\nrow \"p2, k4, p2\"\n"
                            "row \"k2, p1, T3F, k2\"\n");
  // Row 2: "sl 1 to cn, hold in back, k2, p1 from cn" from the back: the held purl shows
  // as a knit on top, moving right over two knits that show as purls.
  EXPECT_EQ(names(p.courses[1]), (std::vector<std::string>{"p", "p", "1/2 RPC", "k", "p", "p"}));
  EXPECT_EQ(names(p.courses[3]), (std::vector<std::string>{"p", "p", "k", "1/2 LPC", "p", "p"}));
  // Equal groups keep their name (2/2 RPC is T4B).
  const Pattern q = run("", "cast_on(8)\nrow \"p2, k4, p2\"\nrow \"k2, 2/2 RPC, k2\"\n");
  EXPECT_EQ(names(q.courses[1]), (std::vector<std::string>{"p", "p", "T4B", "p", "p"}));
  // The face's wrong-side working is the cross again: the mapping is its own inverse.
  for (std::size_t i = 0; i < stitch_table().size(); ++i) {
    const auto id = static_cast<StitchId>(i);
    if (stitch(id).family != StitchFamily::cable) continue;
    const auto face = wrong_side_face(id);
    if (!face) continue;
    SCOPED_TRACE(std::string(stitch(id).name));
    EXPECT_EQ(wrong_side_face(*face), std::optional<StitchId>(id));
    EXPECT_EQ(stitch(*face).consumes, stitch(id).consumes);
    EXPECT_EQ(stitch(*face).cable.purl_background, stitch(id).cable.purl_background);
    // A knit cross shows purled from the back, and a purled one knit again.
    if (!stitch(id).cable.purl_background) {
      EXPECT_NE(stitch(*face).cable.purled, stitch(id).cable.purled);
    }
  }
}

// C4F worked from the back: "sl 2 to cn, hold in front" holds the leftmost two (as the
// face shows them) behind the fabric; they end at the right, and the other two move left
// on top. Every stitch shows as a purl: 2/2 LC purled, drawn with purl loops.
TEST(WrongSideCrosses, AKnitCrossFromTheBackShowsPurlsCrossing) {
  const Pattern p = run("", "cast_on(8)\nrow \"k8\"\nrow \"p2, C4F, p2\"\n");
  EXPECT_EQ(names(p.courses[1]), (std::vector<std::string>{"k", "k", "2/2 LC purled", "k", "k"}));
  const StitchDef& face = stitch(stitch_id("2/2 LC purled"));
  EXPECT_TRUE(purled(face));
  EXPECT_TRUE(face.cable.front);
  EXPECT_EQ(face.cable.held, 2);
  const auto l = layout::lay_out(p);
  for (const auto& loop : l.loops)
    if (loop.course == 2 && loop.wale >= 2 && loop.wale < 6) {
      EXPECT_EQ(loop.shape, layout::Template::purl);
    }
  // An unequal cross changes its numbers as the purl-background ones do: C4B held 2 of 4,
  // 3/1 RC worked so is 1/3 RC purled.
  const Pattern q = run("", "cast_on(8)\nrow \"k8\"\nrow \"p2, 3/1 RC, p2\"\n");
  EXPECT_EQ(names(q.courses[1]), (std::vector<std::string>{"k", "k", "1/3 RC purled", "k", "k"}));
}

// A pattern whose row 1 is printed "(WS)" says so in every notation.
TEST(WrongSideFirst, EveryNotationCanBeginOnAWrongSideRow) {
  const std::string rows = "cast_on(4)\nrow \"k1, p3\"\nrow \"k3, p1\"\n";
  const Pattern field = run(", first_row = \"wrong side\"", rows);
  const Pattern marked = run("", "cast_on(4)\nrow \"(WS) k1, p3\"\nrow \"(RS) k3, p1\"\n");
  const Pattern printed = run("", "cast_on(4)\nknitspeak [[\nRow 1 (WS): k1, p3.\nRow 2: k3, p1.\n]]\n");
  const Pattern charted = run(", first_row = \"wrong side\"", "cast_on(4)\nchart [[\n  | | | .\n  | | | .\n]]\n");
  for (const Pattern* p : {&field, &marked, &printed}) {
    ASSERT_EQ(p->courses.size(), 2u);
    EXPECT_EQ(p->courses[0].side, Side::wrong);
    EXPECT_EQ(names(p->courses[0]), (std::vector<std::string>{"p", "k", "k", "k"}));  // k1 first, at the left
    EXPECT_EQ(names(p->courses[1]), (std::vector<std::string>{"p", "k", "k", "k"}));
  }
  EXPECT_EQ(charted.courses[0].side, Side::wrong);
  EXPECT_EQ(names(charted.courses[0]), (std::vector<std::string>{"k", "k", "k", "p"}));  // drawn as the face looks
  auto error = [](const std::string& fields, const std::string& body) {
    try {
      run(fields, body);
    } catch (const runtime::PatternError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("", "cast_on(4)\nrow \"k4\"\nrow \"(RS) k4\"\n"),
            "t.lua:4: row 2 \"(RS) k4\" is printed as a right-side row but is a wrong-side row of the fabric; check the "
            "rows before it");
  EXPECT_EQ(error(", first_row = \"back\"", ""), "t.lua:1: first_row is \"back\"; use \"right side\" or \"wrong side\"");
}

// A pattern's own abbreviations, declared once for rows, charts and knitspeak alike.
TEST(Glossary, ADeclaredStitchIsReadInRowsChartsAndKnitspeak) {
  const Pattern p = run("", "cast_on(10)\nstitch(\"C4Bp\", \"sl 2 sts to cn, hold in back, k2, p2 from cn\")\n"
                            "stitch(\"B2\", \"knit 2 stitches at each end\")\n"
                            "row \"B2, C4Bp, k2, B2\"\nrow \"p10\"\nchart [[\n  | C4Bp | | | | |\n]]\n"
                            "knitspeak [[\nRow 4: B2, p2, k2, p2, B2.\n]]\n");
  ASSERT_EQ(p.courses.size(), 4u);
  EXPECT_EQ(names(p.courses[0]), (std::vector<std::string>{"k", "k", "k", "k", "T4B", "k", "k"}));
  EXPECT_EQ(names(p.courses[2]), (std::vector<std::string>{"k", "T4B", "k", "k", "k", "k", "k"}));
  EXPECT_EQ(names(p.courses[3]).front(), "p");  // B2 worked on a wrong-side row: k2, purls on the face
  // A knitspeak block's own glossary line does the same.
  const Pattern q = run("", "cast_on(8)\nknitspeak [[\nC6Lp: slip 3 sts to cn and hold in front, p3, k3 from cn.\n"
                            "Row 1: p1, C6Lp, p1.\nRow 2: k1, p3, k3, k1.\n]]\n");
  EXPECT_EQ(names(q.courses[0]), (std::vector<std::string>{"p", "3/3 LPC", "p"}));
  // Quilting's glossary line, as the issue quotes it: a knit worked under the loose strand.
  const Pattern r = run("", "cast_on(7)\nknitspeak [[\nQ1 = insert the needle under the loose strand in front and knit the "
                            "next stitch.\nRow 1 (RS): k2, sl3 wyif, k2.\nRow 2: Purl.\nRow 3: k3, Q1, k3.\n]]\n");
  ASSERT_EQ(r.courses.size(), 3u);
  EXPECT_EQ(names(r.courses[2]), (std::vector<std::string>{"k", "k", "k", "k under float", "k", "k", "k"}));
}

TEST(Glossary, AWorkingKnitcCannotReadIsRefusedWithTheReason) {
  auto error = [](const std::string& body) {
    try {
      run("", "cast_on(8)\n" + body);
    } catch (const runtime::PatternError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("stitch(\"TS\", \"make a tassel\")\n"),
            "t.lua:3: knitc cannot read the working of 'TS' (\"make a tassel\"): give a stitch it knows (knitc reference "
            "lists them), a few of them (\"k2, p2\") or a cross in words (\"sl 2 to cn, hold in front, k2, k2 from cn\")");
  EXPECT_EQ(error("stitch(\"ssk\", \"k2tog\")\n"),
            "t.lua:3: 'ssk' is a stitch knitc knows already; declare a name of the pattern's own");
  EXPECT_EQ(error("stitch(\"Q1\", \"k1 tbl\")\nstitch(\"q1\", \"p1\")\n"), "t.lua:4: 'q1' is declared already at line 3");
  // A knitspeak glossary line knitc cannot read: the row that uses it is refused, its
  // definition quoted.
  EXPECT_EQ(error("knitspeak [[\nTS = make a tassel in the next st.\nRow 1: k3, TS, k4.\n]]\n"),
            "t.lua:5: row 1 of the text uses 'TS', which line 4 defines as \"make a tassel in the next st.\"; knitc cannot "
            "read that working yet: write the row with stitches it knows (knitc reference lists them)");
}

TEST(PrintedFile, BuildsAPrintedPatternWithNoLuaAroundIt) {
  const fs::path dir = test::scratch_dir("printed");
  test::write_text(dir / "seed.txt",
                   "Seed stitch (multiple of 2 sts plus 1)\n\n1st row.\u2014K 1, * p 1, k 1; rep. from * to end.\n"
                   "2nd row.\u2014As 1st row.\n");
  const auto check = test::run_knitc("check " + quoted(dir / "seed.txt"));
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.err.find("seed.txt: 2 rows, 25 stitches cast on, 25 live at the end"), std::string::npos) << check.err;
  // --cast-on wins over the stated multiple; the .glb is written.
  const auto build = test::run_knitc("build " + quoted(dir / "seed.txt") + " --cast-on 11 --gauge 18x24 --weight worsted -o " +
                                     quoted(test::glb_dir() / "printed_seed.glb") + " -q");
  EXPECT_EQ(build.exit_code, 0) << build.err;
  EXPECT_TRUE(fs::exists(test::glb_dir() / "printed_seed.glb"));
  const auto chart = test::run_knitc("chart --cast-on 11 " + quoted(dir / "seed.txt"));
  EXPECT_EQ(chart.out.rfind("# seed: 2 rows on 11 stitches, flat", 0), 0u) << chart.out;
  // A chain selvedge where the text says to slip the first stitch of every row.
  test::write_text(dir / "edged.txt", "Slip the first stitch of every row.\nRow 1: edge st, k4, edge st.\n"
                                      "Row 2: edge st, p4, edge st.\n");
  runtime::PrintedOptions six;
  six.cast_on = 6;
  const Pattern edged = runtime::run_printed_file((dir / "edged.txt").string(), six).pattern;
  EXPECT_EQ(names(edged.courses[0]).back(), "sl wyib");
  six.selvedge = "garter";
  EXPECT_EQ(names(runtime::run_printed_file((dir / "edged.txt").string(), six).pattern.courses[0]).back(), "k");
  // Rounds, when its rows are rounds.
  test::write_text(dir / "rib.txt", "Rnd 1: *k2, p2; rep from *.\nRnd 2: k the knit sts and p the purl sts.\n");
  const auto round = test::run_knitc("chart " + quoted(dir / "rib.txt"));
  EXPECT_NE(round.out.find("in the round"), std::string::npos) << round.out;
  fs::remove_all(dir);
}

TEST(PrintedFile, ProblemsSayWhereAndMisuseExitsTwo) {
  const fs::path dir = test::scratch_dir("printed_bad");
  test::write_text(dir / "bad.txt", "Row 1: k2, p2.\nRow 2: k3tgo.\n");
  const auto bad = test::run_knitc("check --cast-on 8 " + quoted(dir / "bad.txt"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find((dir / "bad.txt").string() + ":2: row 2 \"k3tgo\": unknown stitch 'k3tgo'; did you mean"),
            std::string::npos)
      << bad.err;
  // A printed pattern's options are for printed patterns only.
  const auto lua = test::run_knitc("check --cast-on 8 patterns/jersey.lua");
  EXPECT_EQ(lua.exit_code, 2);
  EXPECT_NE(lua.err.find("--cast-on is for a printed pattern"), std::string::npos) << lua.err;
  EXPECT_EQ(test::run_knitc("check --gauge 22 " + quoted(dir / "bad.txt")).exit_code, 2);
  EXPECT_EQ(test::run_knitc("check --gauge 0x30 " + quoted(dir / "bad.txt")).exit_code, 2);
  EXPECT_EQ(test::run_knitc("check --weight cobweb " + quoted(dir / "bad.txt")).exit_code, 2);
  EXPECT_EQ(test::run_knitc("check --knitting sideways " + quoted(dir / "bad.txt")).exit_code, 2);
  EXPECT_EQ(test::run_knitc("check --cast-on 0 " + quoted(dir / "bad.txt")).exit_code, 2);
  // Nothing to read: a clear error, at line 1.
  test::write_text(dir / "empty.txt", "Just a note about my scarf.\n");
  const auto empty = test::run_knitc("check " + quoted(dir / "empty.txt"));
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.err.find("empty.txt:1: "), std::string::npos) << empty.err;
  fs::remove_all(dir);
}

// A file that is not a pattern's text (knitc's own .glb given back to it, a picture of
// the chart, a PDF, a word processor's document, Windows' UTF-16 text, bytes) is refused
// at once, saying what it is and what to give instead, not read line by line as rows
// that are not rows. A Lua binary chunk is still refused by Lua's loader, by name; and
// the command line exits 1 and writes nothing.
TEST(PrintedFile, AFileThatIsNotTextSaysWhatItIs) {
  using namespace std::string_literals;
  const fs::path dir = test::scratch_dir("not_text");
  const std::vector<std::pair<std::string, std::string>> files = {
      {"front.glb", "glTF\x02\0\0\0"s + "JSON{}"},
      {"chart.png", "\x89PNG\r\n\x1a\n\0\0\0\rIHDR"s},
      {"chart.jpg", "\xFF\xD8\xFF\xE0\0\x10JFIF"s},
      {"pattern.pdf", "%PDF-1.4\n1 0 obj\n<< /Type /Catalog >>\nendobj\n"},
      {"pattern.docx", "PK\x03\x04\x14\0\x06\0"s + "[Content_Types].xml"},
      {"notepad.txt", "\xFF\xFER\0o\0w\0 \0\x31\0:\0 \0k\0\n\0"s},
      {"bytes.txt", "Row 1: k2, p2.\nRow 2: \0\x13\x37.\n"s},
      {"front.lua", "glTF\x02\0\0\0"s + "JSON{}"},
  };
  const std::vector<std::string> said = {"is a glTF binary (a .glb, as knitc writes)", "is an image", "is an image", "is a PDF",
                                         "is zipped", "is UTF-16 text", "holds a NUL byte", "is a glTF binary"};
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path file = dir / files[i].first;
    test::write_text(file, files[i].second);
    SCOPED_TRACE(files[i].first);
    try {
      if (file.extension() == ".lua") runtime::run_pattern_file(file.string());
      else runtime::run_printed_file(file.string(), {});
      ADD_FAILURE() << "read as a pattern";
    } catch (const runtime::PatternError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ":1: the file " + said[i], 0), 0u) << what;
      EXPECT_NE(what.find("; "), std::string::npos) << what;  // and what to give instead
    }
  }
  // A text that only begins like one is read as text.
  test::write_text(dir / "notes.txt", "glTF notes, then the pattern.\nRow 1: k2, p2.\n");
  runtime::PrintedOptions four;
  four.cast_on = 4;
  EXPECT_NO_THROW(runtime::run_printed_file((dir / "notes.txt").string(), four));
  // Lua's own refusal of a binary chunk, which names it.
  test::write_text(dir / "chunk.lua", "\x1bLua\x54\0\x19\x93"s);
  try {
    runtime::run_pattern_file((dir / "chunk.lua").string());
    ADD_FAILURE() << "a binary chunk was run";
  } catch (const runtime::PatternError& e) {
    EXPECT_NE(std::string(e.what()).find("attempt to load a binary chunk"), std::string::npos) << e.what();
  }
  const auto build = test::run_knitc("build " + quoted(dir / "front.glb") + " -o " + quoted(dir / "out.glb"));
  EXPECT_EQ(build.exit_code, 1);
  EXPECT_NE(build.err.find("front.glb:1: the file is a glTF binary"), std::string::npos) << build.err;
  EXPECT_FALSE(fs::exists(dir / "out.glb"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace knitc
