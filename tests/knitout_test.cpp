// Knitout in: the parser's traps, the machine's refusals (each at its line, with the
// program's ;!source:), and real machine programs read into the pattern they knit.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "knit_graph/knit_graph.hpp"
#include "layout/layout.hpp"
#include "measure/crossings.hpp"
#include "measure/measure.hpp"
#include "knitout.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using namespace knitc;
using namespace knitc::knitout;

namespace {

std::string error_of(const std::string& text, const std::string& file = "t.k") {
  try {
    import_text(text, file);
  } catch (const KnitoutError& e) {
    return e.what();
  }
  return "";
}

std::map<std::string, int> tally(const Pattern& p) {
  std::map<std::string, int> n;
  for (const Course& c : p.courses)
    for (const Op& op : c.ops) ++n[std::string(stitch(op.stitch).name)];
  return n;
}

// A flat sheet of `width` needles, cast on by alternate tucks, then `rows` rows of knit.
std::string jersey(int width, int rows, const std::string& eol = "\n") {
  std::string k = ";!knitout-2" + eol + ";;Carriers: 1 2 3" + eol + "inhook 3" + eol;
  for (int n = width; n >= 1; n -= 2) k += "tuck - f" + std::to_string(n) + " 3" + eol;
  for (int n = (width % 2 == 0 ? 1 : 2); n <= width; n += 2) k += "tuck + f" + std::to_string(n) + " 3" + eol;
  for (int r = 0; r < rows; ++r) {
    if (r % 2 == 0)
      for (int n = width; n >= 1; --n) k += "knit - f" + std::to_string(n) + " 3" + eol;
    else
      for (int n = 1; n <= width; ++n) k += "knit + f" + std::to_string(n) + " 3" + eol;
  }
  return k + "outhook 3" + eol;
}

// `n` needles of jersey on the front (cast on by alternate knits, one row), then `rows`
// rows of full-needle rib at racking +0.25: each front needle and the back one facing it.
std::string full_rib_over_jersey(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\n";
  for (int i = n; i >= 1; --i)
    if (i % 2 == 0) k += "knit - f" + std::to_string(i) + " 1\n";
  for (int i = 1; i <= n; ++i)
    if (i % 2 == 1) k += "knit + f" + std::to_string(i) + " 1\n";
  for (int i = n; i >= 1; --i) k += "knit - f" + std::to_string(i) + " 1\n";
  k += "releasehook 1\nrack +0.25\n";
  for (int r = 0; r < rows; ++r)
    if (r % 2 == 0)
      for (int i = 1; i <= n; ++i) k += "knit + f" + std::to_string(i) + " 1\nknit + b" + std::to_string(i) + " 1\n";
    else
      for (int i = n; i >= 1; --i) k += "knit - b" + std::to_string(i) + " 1\nknit - f" + std::to_string(i) + " 1\n";
  return k + "outhook 1\n";
}

// Interlock on `n` needles a bed at racking +0.25: a full-needle row to cast on, then
// courses knitting the front's even needles and the back's odd ones, and the other way.
std::string interlock(int n, int rows) {
  std::string k = ";!knitout-2\n;;Carriers: 1\ninhook 1\nrack +0.25\n";
  for (int i = n; i >= 1; --i) k += "knit - b" + std::to_string(i) + " 1\nknit - f" + std::to_string(i) + " 1\n";
  k += "releasehook 1\n";
  for (int r = 0; r < rows; ++r) {
    const bool right = r % 2 == 0;
    for (int j = 1; j <= n; ++j) {
      const int i = right ? j : n + 1 - j;
      k += std::string("knit ") + (right ? "+ " : "- ") + ((i % 2 == 0) == right ? "f" : "b") + std::to_string(i) + " 1\n";
    }
  }
  return k + "outhook 1\n";
}

// A loop's middle along the course, mm: halfway between its sinker points.
double middle_x(const layout::Loop& l) { return 0.5 * (l.data_points.front().x + l.data_points.back().x); }

fs::path real(const std::string& name) { return test::shared_dir() / "knitout" / "real" / name; }

Imported import_file(const fs::path& path) { return import_text(test::read_text(path), path.filename().string()); }

}  // namespace

TEST(KnitoutParse, ReadsTheTrapsOfRealFiles) {
  const Program p = parse(
      ";!knitout-2\r\n;;Machine: SWG091N2\r\n;;Carriers: A B 3\r\n"
      "inhook A B;glued comment\r\n  tuck - f-3 A B  \r\nrack +0.25\r\nrack 0.0\r\nrack -0.75\r\nknit - b12 \r\n"
      ";; a comment in the body\r\nsplit + fs2 bs3 3\r\nx-vis-color #f0b300 A\r\n",
      "t.k");
  EXPECT_EQ(p.version, 2);
  EXPECT_EQ(p.rails, (std::vector<std::string>{"A", "B", "3"}));
  ASSERT_EQ(p.operations.size(), 8u);
  EXPECT_EQ(p.operations[1].op, Opcode::tuck);
  EXPECT_EQ(p.operations[1].needle, (Needle{Bed::f, -3}));
  EXPECT_EQ(p.operations[1].carriers.size(), 2u);
  EXPECT_DOUBLE_EQ(p.operations[2].racking, 0.25);
  EXPECT_DOUBLE_EQ(p.operations[4].racking, -0.75);
  EXPECT_TRUE(p.operations[5].carriers.empty());  // knit with no yarn: a drop
  EXPECT_EQ(p.operations[5].line, 9);
  EXPECT_EQ(p.operations[6].needle, (Needle{Bed::fs, 2}));
  EXPECT_EQ(p.operations[6].target, (Needle{Bed::bs, 3}));
  EXPECT_EQ(p.operations[7].op, Opcode::extension);
  EXPECT_TRUE(p.warnings.empty());
}

TEST(KnitoutParse, WarnsForAMissingCarriersHeaderAndUnknownExtensions) {
  const Program p = parse(";!knitout-3\ninhook 1\nx-frobnicate 3\n", "t.k");
  ASSERT_EQ(p.warnings.size(), 3u);
  EXPECT_NE(p.warnings[0].find("t.k:1: warning: knitout version 3 is newer"), std::string::npos);
  EXPECT_NE(p.warnings[1].find("t.k:3: warning: unknown extension 'x-frobnicate'"), std::string::npos);
  EXPECT_NE(p.warnings[2].find("no ';;Carriers:' header"), std::string::npos);
}

// koda-knitout's test programs, among others, start at their first operation; CMU's
// visualizer reads such a program with an error shown. knitc reads it with a warning.
TEST(KnitoutParse, ReadsAProgramWithoutItsVersionLineWithAWarning) {
  const Program p = parse("\xEF\xBB\xBFinhook 1\r\ntuck - f2 1\nknit + f2 1\n", "t.k");
  EXPECT_EQ(p.version, 2);
  ASSERT_EQ(p.operations.size(), 3u);
  EXPECT_EQ(p.operations[0].op, Opcode::inhook);
  EXPECT_EQ(p.operations[0].line, 1);
  EXPECT_EQ(p.operations[1].needle, (Needle{Bed::f, 2}));
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_EQ(p.warnings[0], "t.k:1: warning: no ';!knitout-N' version line (knitout requires one); read as knitout-2");
  const Program commented = parse(";; made by hand\n;;Carriers: 1\ninhook 1\n", "t.k");
  EXPECT_EQ(commented.rails, (std::vector<std::string>{"1"}));
  ASSERT_EQ(commented.warnings.size(), 1u);
  EXPECT_NE(commented.warnings[0].find("no ';!knitout-N' version line"), std::string::npos);
}

TEST(KnitoutParse, RefusesWhatIsNotKnitoutAtItsLine) {
  EXPECT_EQ(error_of("Need to try:\nknit + f1 1\n"),
            "t.k:1: the first line is not ';!knitout-N'; a knitout program starts with its version line, like ;!knitout-2");
  EXPECT_NE(error_of(";!knitout-x\nknit + f1 1\n").find("t.k:1: the first line is not ';!knitout-N'"), std::string::npos);
  EXPECT_NE(error_of("\n;!knitout-2\n").find("t.k:1: the first line is not ';!knitout-N'"), std::string::npos);
  EXPECT_EQ(error_of(";!knitout-2\n;;Carriers: 1\ninhook 1\nknot + f1 1\n"),
            "t.k:4: unknown operation 'knot'; knitout's operations are in, inhook, releasehook, out, outhook, knit, tuck, split, "
            "miss, drop, amiss, xfer, rack, stitch, pause and x-... extensions");
  EXPECT_NE(error_of(";!knitout-2\ninhook 1\nknit + g1 1\n").find("t.k:3: 'g1' is not a needle"), std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\ninhook 1\nknit * f1 1\n").find("t.k:3: '*' is not a direction"), std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\nrack one\n").find("t.k:2: 'one' is not a number"), std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\nrack nan\n").find("t.k:2: 'nan' is not a number"), std::string::npos);
  for (const char* huge : {"1000000000", "1e400", "-inf"})
    EXPECT_NE(error_of(std::string(";!knitout-2\nrack ") + huge + "\n").find("t.k:2: the racking " + std::string(huge) + " is out of range"),
              std::string::npos) << huge;
  EXPECT_NE(error_of(";!knitout-2\nxfer f1\n").find("t.k:2: 'xfer' takes 2 arguments, not 1"), std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\nknit + f99999999999 1\n").find("is not a needle"), std::string::npos);
  EXPECT_NE(error_of(std::string(";!knitout-2\nknit + f1 1\0\n", 25)).find("NUL byte"), std::string::npos);
}

TEST(KnitoutMachine, RefusesWhatTheMachineCannotDoWithTheProgramsSource) {
  const std::string head = ";!knitout-2\n;;Carriers: 1 2\n";
  EXPECT_EQ(error_of(head + "knit + f1 1\n"),
            "t.k:3: knit with carrier 1, which is not in; bring it in first with 'inhook 1' (or 'in')");
  EXPECT_EQ(error_of(head + "inhook 1\nknit + f1 1\nrack 1\nxfer f1 b1 ;!source: rib.js:42\n"),
            "t.k:6: xfer from f1 to b1: the needles are not aligned at racking 1 (;!source: rib.js:42); at racking R front needle n "
            "faces back needle n - R: rack 0 first");
  EXPECT_NE(error_of(head + ";!source: lace.js:7\ninhook 1\nknit + f1 1\nxfer f1 f2\n").find("t.k:6: xfer from f1 to f2: both needles are on the same side (;!source: lace.js:7)"),
            std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\n;;Carriers: 1\n;;Width: 10\ninhook 1\nknit + f0 1\nknit + f10 1\n")
                .find("t.k:6: f10 is beyond the machine's bed: the program would span needles 0 to 10, 11 needles, and the swg bed has 10"),
            std::string::npos);
  EXPECT_NE(error_of(";!knitout-2\n;;Machine: Kniterate\n;;Carriers: 1\nrack 5\n").find("t.k:4: racking 5 is beyond the kniterate's reach of 4"),
            std::string::npos);
  EXPECT_NE(error_of(head + "inhook 1\nknit + fs1 1\n").find("knit on slider fs1"), std::string::npos);
  EXPECT_NE(error_of(head + "inhook 1\ninhook 1\n").find("t.k:4: carrier 1 is in already"), std::string::npos);
  EXPECT_NE(error_of(head + "outhook 2\n").find("t.k:3: carrier 2 is not in"), std::string::npos);
  EXPECT_NE(error_of(head + "inhook 1\nrack 1\n").find("t.k:1: the program makes no loops"), std::string::npos);
  // A pile past what a needle can knit off, by tucks, by transfers or by a split: refused
  // at the line that makes it (20,000 tucks on one needle once ran out of memory).
  std::string tucks = head + "inhook 1\n";
  for (int i = 0; i < 20000; ++i) tucks += "tuck + f1 1\n";
  EXPECT_EQ(error_of(tucks + "knit + f1 1\n"), "t.k:12: needle f1 holds 9 loops, past the 8 a needle can knit off; knit the loops off "
                                               "sooner, or spread the tucks or the decrease over more needles");
  std::string stacked = head + "inhook 1\n";
  for (int n = 1; n <= 9; ++n) stacked += "knit + f" + std::to_string(n) + " 1\n";
  stacked += "xfer f1 b1\n";
  for (int n = 2; n <= 9; ++n) stacked += "rack " + std::to_string(n - 1) + "\nxfer f" + std::to_string(n) + " b1\n";
  EXPECT_NE(error_of(stacked).find("t.k:29: needle b1 holds 9 loops"), std::string::npos) << error_of(stacked);
  std::string split = head + "inhook 1\n";
  for (int i = 0; i < 8; ++i) split += "tuck + f1 1\n";
  EXPECT_NE(error_of(split + "tuck + b1 1\nsplit + f1 b1 1\n").find("t.k:13: needle b1 holds 9 loops"), std::string::npos);
}

// One yarn inserting hook: a second inhook before the first carrier is released (or taken
// out) is a warning at its line; knitc still draws what the program knits.
TEST(KnitoutMachine, WarnsOfAnInhookWhileTheHookHoldsAnotherCarrier) {
  const std::string head = ";!knitout-2\n;;Carriers: 1 2\ninhook 1\nknit + f1 1\n";
  const auto hook_warnings = [](const std::string& text) {
    std::vector<std::string> out;
    for (const std::string& w : import_text(text, "t.k").warnings)
      if (w.find("inserting hook") != std::string::npos) out.push_back(w);
    return out;
  };
  const auto held = hook_warnings(head + "inhook 2 ;!source: pocket.py:3\nknit + f2 2\n");
  ASSERT_EQ(held.size(), 1u);
  EXPECT_EQ(held[0], "t.k:5: warning: inhook while carrier 1 is still on the yarn inserting hook (from line 3) (;!source: pocket.py:3); "
                     "a machine has one hook: release it first with 'releasehook 1'");
  EXPECT_TRUE(hook_warnings(head + "releasehook 1\ninhook 2\nknit + f2 2\n").empty());
  EXPECT_TRUE(hook_warnings(head + "outhook 1\ninhook 2\nknit + f2 2\n").empty());
}

TEST(KnitoutMachine, KeepsEachNeedlesPileAndMovesItWhole) {
  const Program p = parse(";!knitout-2\n;;Carriers: 1\ninhook 1\ntuck + f1 1\ntuck + f2 1\nxfer f1 b1\nrack 1\nxfer b1 f2\n"
                          "tuck + f2 1\nknit + f2 1\n", "t.k");
  Machine m(p, profile_for(p));
  for (std::size_t i = 0; i < p.operations.size(); ++i) m.run(i);
  ASSERT_EQ(m.loops().size(), 4u);
  EXPECT_TRUE(m.pile({Bed::f, 1}).empty());
  EXPECT_EQ(m.pile({Bed::f, 2}), std::vector<int>{3});
  // The knit went through the pile bottom to top: f2's own tuck, f1's moved onto it, then the new tuck.
  EXPECT_EQ(m.loops()[3].parents, (std::vector<int>{1, 0, 2}));
}

TEST(KnitoutImport, AJerseySheetIsItsCastOnAndKnitRows) {
  const Imported in = import_text(jersey(6, 4, "\r\n"), "jersey.k");
  const Pattern& p = in.pattern;
  EXPECT_EQ(p.knitting, Knitting::flat);
  EXPECT_EQ(p.cast_on, 6);
  ASSERT_EQ(p.courses.size(), 4u);
  for (const Course& c : p.courses) EXPECT_EQ(test::names(c), std::vector<std::string>(6, "k"));
  EXPECT_EQ(p.courses[0].side, Side::right);  // worked leftwards: from the right edge, face view
  EXPECT_EQ(p.courses[1].side, Side::wrong);
  EXPECT_EQ(p.courses[2].where.line, 4 + 6 + 2 * 6);  // after the header, the tucks and two rows
  EXPECT_EQ(in.front_loops, 6 + 24);
  EXPECT_EQ(in.back_loops, 0);
  EXPECT_NEAR(p.gauge.loop_width, 25.4 / 15.0, 1e-9);  // the SWG-like profile's 15 gauge
}

TEST(KnitoutImport, TransfersSayDecreasesByWhichLoopLiesOnTopAndCablesByWhichSettledFirst) {
  std::string k = jersey(6, 1);
  k.resize(k.size() - std::string("outhook 3\n").size());
  // f2 onto f3 (moved loop on top: from the left, a right-leaning k2tog); f5 onto f4 (ssk).
  k += "xfer f2 b2\nrack 1\nxfer b2 f3\nrack 0\nxfer f5 b5\nrack -1\nxfer b5 f4\nrack 0\n";
  k += "knit + f1 3\nknit + f3 3\nknit + f4 3\nknit + f6 3\n";
  const Pattern p = import_text(k, "t.k").pattern;
  ASSERT_EQ(p.courses.size(), 2u);
  EXPECT_EQ(test::names(p.courses[1]), (std::vector<std::string>{"k", "k2tog", "ssk", "k"}));

  // A 2/2 cross: f1 f2 to the back, the others moved left first, then f1 f2 to f3 f4.
  std::string c = jersey(4, 1);
  c.resize(c.size() - std::string("outhook 3\n").size());
  c += "xfer f1 b1\nxfer f2 b2\nxfer f3 b3\nxfer f4 b4\nrack -2\nxfer b3 f1\nxfer b4 f2\nrack 2\nxfer b1 f3\nxfer b2 f4\nrack 0\n";
  c += "knit + f1 3\nknit + f2 3\nknit + f3 3\nknit + f4 3\n";
  const Pattern q = import_text(c, "t.k").pattern;
  ASSERT_EQ(q.courses.size(), 2u);
  ASSERT_EQ(q.courses[1].ops.size(), 1u);
  const StitchDef& cross = stitch(q.courses[1].ops[0].stitch);
  EXPECT_EQ(cross.family, StitchFamily::cable);
  EXPECT_EQ(cross.cable.held, 2);
  EXPECT_TRUE(cross.cable.front);  // the right pair settled first: on top, moving left (C4F)
  EXPECT_EQ(cross.name, "C4F");
}

// KnitScript's bind-off (ks-cable_swatch_2_cable.k's): from the right, each stitch moved
// onto the back needle left of it, split there (a new loop left on the back needle, the
// old moved onto the front needle beside) and knitted together with that needle's stitch;
// then a row knits the loops the splits left. Each split loop stands over the stitch bound
// off in its column, the two sharing it, so the row is as wide as the sheet (until
// 2026-12-07 the split loops were drawn past the last stitch bound off: twice as wide).
TEST(KnitoutImport, ASplitBindOffLeavesEachSplitLoopOverTheStitchItBoundOff) {
  const int n = 8;
  std::string k = jersey(n, 2);
  k.resize(k.size() - std::string("outhook 3\n").size());
  for (int i = n; i >= 2; --i) {
    const std::string to = std::to_string(i - 1);
    k += "rack 1\nxfer f" + std::to_string(i) + " b" + to + "\nrack 0\nsplit + b" + to + " f" + to + " 3\nknit - f" + to + " 3\n";
  }
  for (int i = 1; i < n; ++i) k += "knit + b" + std::to_string(i) + " 3\n";
  const Pattern p = import_text(k + "outhook 3\n", "bind-off.k").pattern;
  ASSERT_EQ(p.courses.size(), 4u);
  // The bind-off's course, from the left: the chain's last loop (f1) and the loop split
  // over it, then each stitch bound off with the loop split over it, and last the first
  // split (on b7, through f8's stitch, moved there: a purl).
  std::vector<std::string> want{"k", "yo"};
  for (int i = 2; i < n; ++i) want.insert(want.end(), {"bo", i + 1 < n ? "yo" : "p"});
  EXPECT_EQ(test::names(p.courses[2]), want);
  const layout::Layout laid = layout::lay_out(p);
  const double W = laid.loop_width;
  auto width = [&](int c) { return laid.slot_x[static_cast<std::size_t>(c)].back() - laid.slot_x[static_cast<std::size_t>(c)].front(); };
  EXPECT_NEAR(width(3), n * W, 1e-9);      // the bind-off: each column shared
  EXPECT_NEAR(width(4), n * W, 1e-9);  // the split loops knitted, the chain's last held
  // Each split loop within the column of a stitch of the row below (at most half a loop
  // width from its middle: the stitch bound off shares the column), and knitted by the
  // last row's loop over it.
  int split_loops = 0;
  for (const layout::Loop& l : laid.loops) {
    if (l.course != 3 || stitch(l.stitch).name != "yo") continue;
    ++split_loops;
    const double x = middle_x(l);
    double nearest = 1e9;
    for (const layout::Loop& below : laid.loops)
      if (below.course == 2) nearest = std::min(nearest, std::abs(middle_x(below) - x));
    EXPECT_LE(nearest, 0.5 * W + 1e-9) << "a split loop at x " << x << " mm stands over no stitch of the row below";
  }
  EXPECT_EQ(split_loops, n - 2);
}

TEST(KnitoutImport, HandDerivedLoopCountsOfSmallRealPrograms) {
  KNITC_NEED_SHARED(real("cmu-helloworld.k"));
  // helloworld: 20 tucks on f1..f20, then 20 rows of 20 knits, all on the front bed.
  const Imported hello = import_file(real("cmu-helloworld.k"));
  EXPECT_EQ(hello.front_loops, 20 + 20 * 20);
  EXPECT_EQ(hello.back_loops, 0);
  EXPECT_EQ(hello.pattern.cast_on, 20);
  EXPECT_EQ(hello.pattern.courses.size(), 20u);
  EXPECT_EQ(tally(hello.pattern)["k"], 400);
  // rib1x1: front f2..f20 (10), back b1..b19 (10); a tuck on each, then 41 rows of knits
  // on all 20, bar b1 in the first, which goes rightwards from f2 (b1 was tucked last).
  const Imported rib = import_file(real("cmu-rib1x1.k"));
  EXPECT_EQ(rib.front_loops, 10 + 41 * 10);
  EXPECT_EQ(rib.back_loops, 10 + 41 * 10 - 1);
  const auto n = tally(rib.pattern);
  EXPECT_GT(n.at("k"), 300);
  EXPECT_GT(n.at("p"), 300);
  // viz-cross-test: carriers A, B and C knit (D is brought in and never used): a yarn each.
  const Imported cross = import_file(real("viz-cross-test.k"));
  EXPECT_EQ(cross.pattern.yarns.size(), 3u);
  // Front: B on f1 f2 f4 f5 and back on f5, then A, C, and A with C plated, 5 each;
  // back: A, C and the plated pair, 5 each.
  EXPECT_EQ(cross.front_loops, 5 + 5 + 5 + 5);
  EXPECT_EQ(cross.back_loops, 5 + 5 + 5);
}

// CMU's full-needle, Milano and half-Milano ribs (tests/knitout/SOURCES.md): each knit
// makes one loop on its bed, and none of the three tucks, splits or transfers.
TEST(KnitoutImport, HandDerivedLoopCountsOfDoubleBedRibs) {
  const fs::path ours = fs::path(KNITC_SOURCE_DIR) / "tests" / "knitout";
  // Every one: an alternate-needle cast-on on the front (half the needles, then the
  // rest), three rows of jersey, then the rib at racking +0.25.
  // Full rib: 80 front needles, 79 back; 120 rows on both beds.
  const Imported full = import_file(ours / "cmu-fullrib.knitout");
  EXPECT_EQ(full.front_loops, 40 + 40 + 3 * 80 + 120 * 80);
  EXPECT_EQ(full.back_loops, 120 * 79);
  // Milano rib: 80 needles a bed; 40 times a row on both beds, a pass on the front alone
  // and one on the back alone (each bed knits twice in three passes).
  const Imported milano = import_file(ours / "cmu-MilanoRib.knitout");
  EXPECT_EQ(milano.front_loops, 40 + 40 + 3 * 80 + 60 * 2 * 80);
  EXPECT_EQ(milano.back_loops, 60 * 2 * 80);
  // Half-Milano: 70 needles a bed; 90 times a row on both beds, then a pass on the back.
  const Imported half = import_file(ours / "cmu-halfmilano.knitout");
  EXPECT_EQ(half.front_loops, 35 + 35 + 3 * 70 + 90 * 70);
  EXPECT_EQ(half.back_loops, 90 * 2 * 70);
  // Drawn as one layer (docs/knitout.md), each read exactly: the front bed's loops are
  // knits, the back's purls, and the back bed's first loops, knitted on empty needles,
  // yarn overs (one a back needle); the cast-on is the front's first two passes.
  const std::pair<const Imported*, int> ribs[] = {{&full, 79}, {&milano, 80}, {&half, 70}};
  for (const auto& [in, back_needles] : ribs) {
    for (const std::string& w : in->warnings) EXPECT_EQ(w.find("approximately"), std::string::npos) << w;
    auto n = tally(in->pattern);
    EXPECT_EQ(n["yo"], back_needles);
    EXPECT_EQ(n["k"] + n["p"] + n["yo"] + in->pattern.cast_on, in->front_loops + in->back_loops);
  }
}

TEST(KnitoutImport, BothBedsLoopsInOneNeedleColumnShareItsWidth) {
  // A full-needle rib is as wide as the jersey it grows from on the same needles: each
  // front loop and the back loop facing it half a needle position, not one each.
  const Pattern rib = import_text(full_rib_over_jersey(12, 4), "fr.k").pattern;
  const layout::Layout laid = layout::lay_out(rib);
  const double W = laid.loop_width;
  ASSERT_EQ(laid.courses, 1 + 5);
  EXPECT_TRUE(rib.courses[0].widths.empty()) << "the jersey row keeps whole positions";
  for (int c = 2; c < laid.courses; ++c) {
    ASSERT_EQ(rib.courses[static_cast<std::size_t>(c - 1)].widths, std::vector<double>(24, 0.5)) << "course " << c;
    EXPECT_NEAR(layout::course_width(laid, c), layout::course_width(laid, 1), 1e-9) << "course " << c;
  }
  // Each front loop of the first rib row lies over its parent, within a quarter of a
  // position (its parent's needle's half), not fanned out to twice the distance.
  std::vector<const layout::Loop*> jersey_row, first_rib;
  for (const layout::Loop& l : laid.loops) {
    if (l.course == 1) jersey_row.push_back(&l);
    if (l.course == 2 && l.wale % 2 == 0) first_rib.push_back(&l);
  }
  ASSERT_EQ(jersey_row.size(), 12u);
  ASSERT_EQ(first_rib.size(), 12u);
  std::sort(jersey_row.begin(), jersey_row.end(), [](auto* a, auto* b) { return a->wale < b->wale; });
  std::sort(first_rib.begin(), first_rib.end(), [](auto* a, auto* b) { return a->wale < b->wale; });
  for (std::size_t i = 0; i < 12; ++i) EXPECT_NEAR(middle_x(*first_rib[i]), middle_x(*jersey_row[i]), 0.3 * W) << "needle " << i + 1;

  // An interlock's two layers: a course knits one bed's loop of each column and leaves
  // the other, so the loop it knits takes the column's width (all but a tenth) and lies
  // over the other bed's loop of that column, knitted the course before.
  const Pattern inter = import_text(interlock(12, 6), "interlock.k").pattern;
  const layout::Layout two = layout::lay_out(inter);
  ASSERT_EQ(two.courses, 1 + 6);
  EXPECT_EQ(inter.cast_on_widths, std::vector<double>(24, 0.5));
  for (int c = 2; c + 1 < two.courses; ++c) {
    std::map<int, const layout::Loop*> next;
    for (const layout::Loop& l : two.loops)
      if (l.course == c + 1) next[l.wale] = &l;
    int pairs = 0;
    for (const layout::Loop& l : two.loops) {
      if (l.course != c) continue;
      EXPECT_NEAR(inter.courses[static_cast<std::size_t>(c - 1)].widths[static_cast<std::size_t>(l.wale)], 1.0 / 1.1, 1e-12);
      const auto other = next.find(l.wale ^ 1);  // the column's other bed
      ASSERT_NE(other, next.end()) << "course " << c << " wale " << l.wale;
      EXPECT_NEAR(middle_x(l), middle_x(*other->second), 0.2 * two.loop_width) << "course " << c << " wale " << l.wale;
      ++pairs;
    }
    EXPECT_EQ(pairs, 12);
  }
  // Each bed knits every other course, so the courses rise half a course each and every
  // loop stands a course above the one it was pulled through (two courses, twice as
  // tall as an interlock's, before 2026-12-07).
  const knit_graph::Graph graph = knit_graph::build(inter);
  for (std::size_t i = 0; i < graph.loops.size(); ++i) {
    const auto& k = graph.loops[i];
    if (k.course < 3 || k.parents.size() != 1) continue;
    const int below = graph.loops[static_cast<std::size_t>(k.parents.front())].course;
    EXPECT_NEAR(layout::course_y(two, k.course) - layout::course_y(two, below), two.course_spacing, 1e-9) << "loop " << i;
  }

  // A rib on alternate needles of each bed is full gauge: its loops are as wide as a
  // jersey's, one needle pitch, whole positions.
  std::string alternate = ";!knitout-2\n;;Carriers: 1\ninhook 1\n";
  for (int r = 0; r < 6; ++r)
    for (int j = 1; j <= 12; ++j) {
      const int i = r % 2 == 0 ? 13 - j : j;
      alternate += std::string("knit ") + (r % 2 == 0 ? "- " : "+ ") + (i % 2 ? "f" : "b") + std::to_string(i) + " 1\n";
    }
  const Pattern rib_1x1 = import_text(alternate + "outhook 1\n", "rib.k").pattern;
  EXPECT_DOUBLE_EQ(rib_1x1.gauge.loop_width, import_text(jersey(12, 4), "j.k").pattern.gauge.loop_width);
  for (const Course& c : rib_1x1.courses) EXPECT_TRUE(c.widths.empty());
}

TEST(KnitoutImport, AFullNeedleRibOverJerseyRelaxesWithoutPassingYarnsThrough) {
  // Laid twice as wide as its jersey, the rib's first row fanned out over 60 needles and
  // relaxing passed 562 of 5,854 crossings through (docs/knitout.md).
  const Pattern rib = import_text(full_rib_over_jersey(60, 2), "fr.k").pattern;
  const CompileOptions options = test::centrelines(true);
  const Fabric f = compile(rib, options);
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
  EXPECT_FALSE(cores_left_overlapping(f, options.relaxation)) << f.relaxation.end_overlap;
}

TEST(KnitoutImport, RealProgramsSayTheirStructures) {
  KNITC_NEED_SHARED(real("cmu-garter.knitout"));
  // Garter by transfers: every row is all knit or all purl, turn about.
  const Pattern garter = import_file(real("cmu-garter.knitout")).pattern;
  int knit_rows = 0, purl_rows = 0;
  for (const Course& c : garter.courses) {
    const auto names = test::names(c);
    knit_rows += std::all_of(names.begin(), names.end(), [](const std::string& s) { return s == "k"; });
    purl_rows += std::all_of(names.begin(), names.end(), [](const std::string& s) { return s == "p"; });
  }
  EXPECT_GT(knit_rows, 50);
  EXPECT_GT(purl_rows, 50);
  // Lace: yarn overs beside decreases of both leans.
  auto lace = tally(import_file(real("cmu-lace.knitout")).pattern);
  EXPECT_GT(lace["yo"], 50);
  EXPECT_GT(lace["k2tog"], 20);
  EXPECT_GT(lace["ssk"], 20);
  // A machine-knit braid: crosses.
  int crosses = 0;
  for (const Course& c : import_file(real("knitdb-22_1_083Braid.knitout")).pattern.courses)
    for (const Op& op : c.ops) crosses += stitch(op.stitch).family == StitchFamily::cable;
  EXPECT_GT(crosses, 10);
  // A tube knitted on both beds: in the round.
  EXPECT_EQ(import_file(real("mil-tube.k")).pattern.knitting, Knitting::round);
  // Plating: each of its 7,500 stitches knitted with carriers 3 and 4 (counted from its
  // text: "knit D N 3 4") is plated, carrier 3's yarn first; a bind-off's steps are bo.
  const Imported plating = import_file(real("mil-plating.k"));
  int plated = 0;
  for (const Course& c : plating.pattern.courses)
    for (const Op& op : c.ops)
      if (op.plated >= 0) plated += plating.pattern.yarns[static_cast<std::size_t>(op.yarn)].id == "3" &&
                                   plating.pattern.yarns[static_cast<std::size_t>(op.plated)].id == "4";
  EXPECT_EQ(plated, 7500);
  EXPECT_GT(tally(plating.pattern)["bo"], 40);
  // The decreasing triangle narrows from 22 to 2.
  const Pattern dec = import_file(real("ks-dec_triangle.k")).pattern;
  EXPECT_EQ(dec.cast_on, 22);
  EXPECT_EQ(produced(dec.courses.back()), 2);
}

// A half-gauge tube whose knit/purl image moves loops between the beds: its front layer
// is knitted going left on the even needles, its back layer going right on the odd ones,
// each layer's purls on the other bed, and between the passes the loops are parked on
// either bed. Read in the round, every course exactly, 201 stitches round; its purls are
// the knits on a layer's other bed, counted here from the program's text.
TEST(KnitoutImport, AHalfGaugeTubeWithPurlsIsReadInTheRoundByItsLayers) {
  KNITC_NEED_SHARED(real("cmu-image-tube-diag.k"));
  const std::string text = test::read_text(real("cmu-image-tube-diag.k"));
  int purls_in_text = 0, knits_in_text = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("knit ")) continue;
    ++knits_in_text;
    purls_in_text += line.starts_with("knit - b") || line.starts_with("knit + f");
  }
  ASSERT_GT(purls_in_text, 1000);
  const Imported tube = import_file(real("cmu-image-tube-diag.k"));
  EXPECT_EQ(tube.pattern.knitting, Knitting::round);
  for (const std::string& w : tube.warnings) EXPECT_EQ(w.find("approximately"), std::string::npos) << w;
  for (const Course& c : tube.pattern.courses) ASSERT_EQ(produced(c), 201) << c.where.line;
  auto t = tally(tube.pattern);
  EXPECT_EQ(t["p"], purls_in_text);
  EXPECT_EQ(t["k"] + t["p"], knits_in_text);
}

// A knit/purl image on a plain ground (CMU's, tests/knitout/SOURCES.md): most of its
// interior repeats, so it is relaxed by the ground's tile, the image relaxed with the
// edges against the held ground; no yarn passes through another, no cores overlap.
TEST(KnitoutImport, AnImageOnAPlainGroundIsRelaxedByTheGroundsRepeat) {
  const Imported image = import_file(fs::path(KNITC_SOURCE_DIR) / "tests" / "knitout" / "cmu-image-kp-half-rib.k");
  const Fabric f = compile(image.pattern, test::centrelines(true));
  EXPECT_GT(f.relaxation.repeat_wales, 0);
  EXPECT_GT(f.relaxation.held_share, 0.1);
  EXPECT_LT(f.relaxation.held_share, 0.9) << "the image is not held";
  EXPECT_LE(measure::measure(image.pattern, f.layout, f.pieces).deepest_core_penetration, 0.05);
  ASSERT_TRUE(f.crossings_checked);
  EXPECT_EQ(measure::passed_through(f.crossings), 0u);
}

TEST(KnitoutImport, EveryRealProgramReadsIntoAPatternTheKnitGraphTakes) {
  KNITC_NEED_SHARED(real("cmu-helloworld.k"));
  int programs = 0, exact = 0;
  const fs::path ours = fs::path(KNITC_SOURCE_DIR) / "tests" / "knitout";
  for (const fs::path& dir : {real(""), ours})
    for (const auto& entry : fs::directory_iterator(dir)) {
      // Programs only: the SOURCES.md and licences kept beside them are not.
      if (entry.path().extension() != ".k" && entry.path().extension() != ".knitout") continue;
      SCOPED_TRACE(entry.path().filename().string());
      const Imported in = import_file(entry.path());
      EXPECT_GT(in.pattern.courses.size(), 0u);
      EXPECT_NO_THROW(knit_graph::build(in.pattern));
      ++programs;
      const bool read_exactly = std::none_of(in.warnings.begin(), in.warnings.end(), [](const std::string& w) {
        return w.find("approximately") != std::string::npos || w.find("drawn bound off") != std::string::npos;
      });
      exact += read_exactly;
      if (dir == ours) {  // the programs found here (tests/knitout/SOURCES.md)
        EXPECT_TRUE(read_exactly);
      }
    }
  EXPECT_EQ(programs, 27 + 13);
  // Read exactly (no course approximated, no drop drawn bound off): 20 of the 27 and the 13 found.
  EXPECT_GE(exact, 33);
}
