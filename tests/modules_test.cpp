// The pattern library (patterns/lib: ribs, cables, lace): each library function makes
// the same fabric as the rows written out by hand, flat and in the round; bad arguments
// are errors at the caller's line. How require finds and runs modules: require_test.cpp.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime.hpp"
#include "support.hpp"
#include "language/chart.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

namespace fs = std::filesystem;
using runtime::PatternError;

using test::library_script;
using test::run_with_library;

// The message the script fails with, or "" if it runs.
std::string error_of(const std::string& knitting, int stitches, const std::string& body) {
  return test::script_error(library_script(knitting, stitches, body));
}

// The library call and the rows written by hand make one fabric (Pattern's == ignores
// where each row was written); on failure both charts are shown.
::testing::AssertionResult same_fabric(const std::string& knitting, int stitches, const std::string& library,
                                       const std::string& by_hand) {
  Pattern a, b;
  try {
    a = run_with_library(knitting, stitches, library);
    b = run_with_library(knitting, stitches, by_hand);
  } catch (const PatternError& e) {
    return ::testing::AssertionFailure() << knitting << ", " << stitches << " sts: " << e.what();
  }
  if (a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << knitting << ", " << stitches << " sts: " << library
                                       << "\nthe library made:\n" << language::chart_text(a)
                                       << "\nby hand:\n" << language::chart_text(b);
}

const std::vector<std::string> both = {"round", "flat"};

// The names a module exports, sorted.
std::string exports_of(const std::string& module) {
  const std::string message = test::script_error(
      "local names = {}\nfor name in pairs(require \"" + module + "\") do names[#names + 1] = name end\n"
      "table.sort(names)\nerror(table.concat(names, \" \"), 0)\n");
  return message.substr(message.find(": ") + 2);  // after "t.lua:4: "
}

// The functions a module declares (working.declare, which the reference prints), sorted.
std::string declared_by(const std::string& module) {
  const std::string message = test::script_error(
      "require \"" + module + "\"\nlocal names = {}\n"
      "for _, f in ipairs(require \"working\".declared[\"" + module + "\"].functions) do\n"
      "  names[#names + 1] = f.call:match(\"^[%w_]+%.([%w_]+)\")\nend\n"
      "table.sort(names)\nerror(table.concat(names, \" \"), 0)\n");
  return message.substr(message.find(": ") + 2);
}

TEST(ModulesLibrary, EveryModuleDeclaresExactlyWhatItExports) {
  for (const char* module : {"ribs", "cables", "lace"}) EXPECT_EQ(declared_by(module), exports_of(module)) << module;
}

// Each argument of each library function is checked as its declaration says, in the very
// words the reference prints in its "takes" column: a value no declaration allows (a
// table) in that argument alone, the others valid, fails with that text.
TEST(ModulesLibrary, EveryArgumentIsCheckedAsTheReferenceSays) {
  const std::string checks = R"lua(
local failures, count = {}, 0
local function valid(arg)
  if arg.default ~= nil then return arg.default end
  if arg.values then return arg.values[1] end
  if arg.choices then return arg.choices[1] end
  return arg.least or 1
end
for _, module in ipairs({ "cables", "lace", "ribs" }) do
  for _, f in ipairs(require "working".declared[module].functions) do
    local name = f.call:match("^([%w_]+%.[%w_]+)")
    local fn = require(module)[name:match("%.(.*)$")]
    local table_call = f.call:find("{", 1, true) ~= nil
    for i, arg in ipairs(f.declaration) do
      local values = {}
      for j, other in ipairs(f.declaration) do values[j] = valid(other) end
      values[i] = {}
      local ok, message
      if table_call then
        local t = {}
        for j, other in ipairs(f.declaration) do t[other[1]] = values[j] end
        ok, message = pcall(fn, t)
      else
        ok, message = pcall(fn, table.unpack(values, 1, #f.declaration))
      end
      local expected = name .. ": " .. arg[1] .. " must be " .. f.args[i][2] .. ", not a table"
      count = count + 1
      if ok or not message:find(expected, 1, true) then failures[#failures + 1] = expected .. " <- " .. tostring(message) end
    end
  end
end
error(count .. " checked; " .. table.concat(failures, "; "), 0)
)lua";
  const std::string message = error_of("flat", 14, checks);
  EXPECT_EQ(message.substr(message.find(": ") + 2), "20 checked; ") << message;
}

TEST(ModulesLibrary, ExportsExactlyTheFunctionsTestedHere) {
  EXPECT_EQ(exports_of("ribs"), "garter k1p1 k2p2 moss rib seed");
  EXPECT_EQ(exports_of("cables"), "horseshoe rope");
  EXPECT_EQ(exports_of("lace"), "chevron eyelet_row feather_and_fan");
}

// A piece whose row 1 was worked from the wrong side (a set-up row, as knitspeak's
// "Row 1 (WS):" says): every library function works its rows on the sides they are, and
// its rhythm starts from the next right-side row, as a chart of the pattern would.
TEST(ModulesLibrary, EveryFunctionWorksAfterAWrongSideFirstRow) {
  const std::string setup = "knitspeak [[\nRow 1 (WS): Purl.\n]]\n";
  const std::pair<int, std::pair<std::string, std::string>> cases[] = {
      {12, {"ribs.k2p2(2)", "rows(2, \"k2, p2\")"}},
      {10, {"ribs.k1p1(2)", "rows(2, \"k1, p1\")"}},
      {12, {"ribs.rib(2, 2, 1)", "row \"k2, p1\" row \"k1, p2\""}},
      {8, {"ribs.garter(2)", "rows(2, \"k\")"}},
      {8, {"ribs.seed(2)", "row \"k1, p1\" row \"p1, k1\""}},
      {8, {"ribs.moss(4)", "rows(2, \"p1, k1\") rows(2, \"k1, p1\")"}},
      {14, {"cables.rope { rows = 4 }",
            "row \"p2, C4F, p2, C4F, p2\" row \"k2, p4, k2, p4, k2\" row \"p2, k4, p2, k4, p2\" row \"k2, p4, k2, p4, k2\""}},
      {12, {"cables.horseshoe { rows = 4 }", "row \"p2, C4B, C4F, p2\" row \"k2, p8, k2\" row \"p2, k8, p2\" row \"k2, p8, k2\""}},
      {8, {"lace.eyelet_row(3)", "row \"k1, (yo, k2tog) x3, k1\" row \"p\" row \"k\""}},  // was p2tog on the right side
      {8, {"lace.chevron(2)", "row \"k1, yo, k2, cdd, k2, yo\" row \"p\""}},
      {18, {"lace.feather_and_fan(4)",
            "row \"(k2tog) x3, (yo, k1) x6, (k2tog) x3\" row \"k\" row \"k\" row \"p\""}},
  };
  for (const auto& [stitches, call] : cases)
    EXPECT_TRUE(same_fabric("flat", stitches, setup + call.first, setup + call.second)) << call.first;
}

TEST(ModulesLibrary, RightSideIsTheRuntimesRule) {
  const auto p = run_with_library("flat", 4, "knitspeak [[\nRow 1 (WS): Purl.\n]]\n"
                                "assert(right_side() and not right_side(1) and right_side(2) and not right_side(3))\n"
                                "row \"k\"\nassert(not right_side())\n");
  EXPECT_EQ(p.courses.size(), 2u);
  EXPECT_TRUE(run_with_library("round", 4, "assert(right_side(1) and right_side(2)) row \"k\" assert(right_side())").courses.size() == 1);
  EXPECT_TRUE(run_with_library("flat", 4, "assert(right_side() and not right_side(2)) row \"k\" assert(not right_side())").courses.size() == 1);
}

// ---- ribs ----

TEST(ModulesRibs, K2p2IsTheWrittenRib) {
  for (const auto& k : both) {
    EXPECT_TRUE(same_fabric(k, 12, "ribs.k2p2(4)", "rows(4, \"k2, p2\")"));
    // 4 x 3 + 2: starts and ends with k2, the wrong side written as it faces the knitter.
    EXPECT_TRUE(same_fabric(k, 14, "ribs.k2p2(3)",
                            k == "flat" ? "row \"k2, (p2, k2) x3\" row \"p2, (k2, p2) x3\" row \"k2, (p2, k2) x3\""
                                        : "rows(3, \"k2, (p2, k2) x3\")"));
  }
  // Drawn as the face looks, flat or round: the knit columns stack.
  for (const auto& k : both) EXPECT_TRUE(same_fabric(k, 8, "ribs.k2p2(3)", "chart { [[\n. . | |\n]], rep = 3 }"));
}

TEST(ModulesRibs, K1p1IsTheWrittenRib) {
  for (const auto& k : both) EXPECT_TRUE(same_fabric(k, 10, "ribs.k1p1(5)", "rows(5, \"k1, p1\")"));
  EXPECT_TRUE(same_fabric("flat", 9, "ribs.k1p1(4)", "for i = 1, 2 do row \"k1, (p1, k1) x4\" row \"p1, (k1, p1) x4\" end"));
  EXPECT_TRUE(same_fabric("round", 9, "ribs.k1p1(4)", "rows(4, \"k1, (p1, k1) x4\")"));
}

TEST(ModulesRibs, AnyRibOfKnitsAndPurls) {
  // k2, p1 flat: the wrong side reads k1, p2; the face shows the same columns every row.
  EXPECT_TRUE(same_fabric("flat", 12, "ribs.rib(4, 2, 1)", "for i = 1, 2 do row \"k2, p1\" row \"k1, p2\" end"));
  for (const auto& k : both) EXPECT_TRUE(same_fabric(k, 12, "ribs.rib(4, 2, 1)", "chart { [[\n. | |\n]], rep = 4 }"));
  EXPECT_TRUE(same_fabric("round", 12, "ribs.rib(2, 3, 1)", "rows(2, \"k3, p1\")"));
  // 3 x 3 + 2: k2 at both edges.
  EXPECT_TRUE(same_fabric("flat", 11, "ribs.rib(2, 2, 1)", "row \"k2, (p1, k2) x3\" row \"p2, (k1, p2) x3\""));
  // 1.0e0 counts as 1, as in the verbs.
  EXPECT_TRUE(same_fabric("round", 10, "ribs.rib(2.0, 1.0, 1)", "rows(2, \"k1, p1\")"));
}

TEST(ModulesRibs, GarterKnitsEveryRowFlatAndAlternatesInTheRound) {
  EXPECT_TRUE(same_fabric("flat", 10, "ribs.garter(4)", "rows(4, \"k\")"));
  EXPECT_TRUE(same_fabric("round", 10, "ribs.garter(4)", "row \"k\" row \"p\" row \"k\" row \"p\""));
  for (const auto& k : both) EXPECT_TRUE(same_fabric(k, 7, "ribs.garter(6)", "chart { [[\n.\n|\n]], rep = 3 }"));
  // It follows the row numbers: after an odd number of rows a call continues the ridges.
  EXPECT_TRUE(same_fabric("round", 6, "row \"k\" ribs.garter(3)", "row \"k\" row \"p\" row \"k\" row \"p\""));
  EXPECT_TRUE(same_fabric("flat", 6, "row \"k\" ribs.garter(2) ribs.garter(1)", "rows(4, \"k\")"));
}

TEST(ModulesRibs, SeedMovesOverOneStitchEveryRow) {
  for (const auto& k : both) {
    EXPECT_TRUE(same_fabric(k, 8, "ribs.seed(4)", "for i = 1, 2 do row \"k1, p1\" row \"p1, k1\" end"));
    EXPECT_TRUE(same_fabric(k, 8, "ribs.seed(4)", "chart { [[\n| .\n. |\n]], rep = 2 }"));
    EXPECT_TRUE(same_fabric(k, 8, "row \"k\" ribs.seed(2)", "row \"k\" row \"p1, k1\" row \"k1, p1\""));
  }
  // An odd count flat: every row k1, *p1, k1, as a knitter writes it.
  EXPECT_TRUE(same_fabric("flat", 7, "ribs.seed(4)", "rows(4, \"k1, *p1, k1; rep from *\")"));
  EXPECT_TRUE(same_fabric("round", 7, "ribs.seed(4)", "for i = 1, 2 do row \"k1, (p1, k1) x3\" row \"p1, (k1, p1) x3\" end"));
  for (const auto& k : both)
    EXPECT_TRUE(same_fabric(k, 7, "ribs.seed(2)", "chart [[\n. | . | . | .\n| . | . | . |\n]]"));
}

TEST(ModulesRibs, MossIsUsMossStitchAFourRowRepeat) {
  for (const auto& k : both) {
    EXPECT_TRUE(same_fabric(k, 8, "ribs.moss(8)",
                            "for i = 1, 2 do rows(2, \"k1, p1\") rows(2, \"p1, k1\") end"));
    EXPECT_TRUE(same_fabric(k, 6, "ribs.moss(6)", "chart { [[\n| .\n| .\n. |\n. |\n]] } chart [[\n. |\n. |\n]]"));
  }
  // An odd count flat: rows 1 and 4 k1, *p1, k1; rows 2 and 3 p1, *k1, p1.
  EXPECT_TRUE(same_fabric("flat", 9, "ribs.moss(4)",
                          "row \"k1, (p1, k1) x4\" rows(2, \"p1, (k1, p1) x4\") row \"k1, (p1, k1) x4\""));
}

// ---- cables ----

TEST(ModulesCables, RopeDefaultsToC4FEveryFourRowsBetweenTwoPurls) {
  // 14 = (4 + 2) x 2 + 2; crossings on rows 3 and 7, right-side rows when flat.
  const std::string rs = "row \"p2, k4, p2, k4, p2\"\n", ws = "row \"k2, p4, k2, p4, k2\"\n",
                    cross = "row \"p2, C4F, p2, C4F, p2\"\n";
  EXPECT_TRUE(same_fabric("flat", 14, "cables.rope { rows = 8 }", rs + ws + cross + ws + rs + ws + cross + ws));
  EXPECT_TRUE(same_fabric("round", 14, "cables.rope { rows = 8 }", rs + rs + cross + rs + rs + rs + cross + rs));
}

TEST(ModulesCables, RopeOptions) {
  // C6B every 3 rows with no purls between: rounds 2 and 5 cross.
  EXPECT_TRUE(same_fabric("round", 12, "cables.rope { rows = 6, width = 6, cross = \"back\", cross_every = 3, purl_border = 0 }",
                          "row \"k12\" row \"C6B, C6B\" rows(2, \"k\") row \"(C6B) x2\" row \"k\""));
  // C8F every 8 rows flat, one purl around: rows 7 and 15 cross.
  const std::string rs = "row \"p1, k8, p1, k8, p1\"\n", ws = "row \"k1, p8, k1, p8, k1\"\n",
                    cross = "row \"p1, C8F, p1, C8F, p1\"\n";
  std::string by_hand;
  for (int r = 1; r <= 16; ++r) by_hand += r % 8 == 7 ? cross : r % 2 == 1 ? rs : ws;
  EXPECT_TRUE(same_fabric("flat", 19, "cables.rope { rows = 16, width = 8, cross_every = 8, purl_border = 1 }", by_hand));
  // C2B every right-side row.
  EXPECT_TRUE(same_fabric("flat", 10, "cables.rope { rows = 4, width = 2, cross = \"back\", cross_every = 2 }",
                          "for i = 1, 2 do row \"p2, C2B, p2, C2B, p2\" row \"k2, p2, k2, p2, k2\" end"));
}

TEST(ModulesCables, ACalledAgainPanelKeepsItsRhythm) {
  // The crossings follow the row numbers: rows 3, 7 and 11 whether in one call or three.
  for (const auto& k : both)
    EXPECT_TRUE(same_fabric(k, 8, "cables.rope { rows = 5 } cables.rope { rows = 2 } cables.rope { rows = 5 }",
                            "cables.rope { rows = 12 }"));
  // Rows worked before the panel count too: its first crossing is row 7, not its own row 3.
  EXPECT_TRUE(same_fabric("round", 8, "rows(4, \"p2, k4, p2\") cables.rope { rows = 4 }",
                          "rows(6, \"p2, k4, p2\") row \"p2, C4F, p2\" row \"p2, k4, p2\""));
}

TEST(ModulesCables, HorseshoeCrossesBothWaysFromTheCentre) {
  const std::string rs = "row \"p2, k8, p2\"\n", ws = "row \"k2, p8, k2\"\n", cross = "row \"p2, C4B, C4F, p2\"\n";
  EXPECT_TRUE(same_fabric("flat", 12, "cables.horseshoe { rows = 6 }", rs + ws + cross + ws + rs + ws));
  EXPECT_TRUE(same_fabric("round", 12, "cables.horseshoe { rows = 6 }", rs + rs + cross + rs + rs + rs));
  // 12 wide, a purl between, crossing on every right-side row.
  EXPECT_TRUE(same_fabric("flat", 27, "cables.horseshoe { rows = 4, width = 12, cross_every = 2, purl_border = 1 }",
                          "for i = 1, 2 do row \"p1, C6B, C6F, p1, C6B, C6F, p1\" row \"k1, p12, k1, p12, k1\" end"));
}

// ---- lace ----

TEST(ModulesLace, EyeletRow) {
  for (const auto& k : both) EXPECT_TRUE(same_fabric(k, 10, "lace.eyelet_row()", "row \"k1, (yo, k2tog) x4, k1\""));
  EXPECT_TRUE(same_fabric("flat", 10, "lace.eyelet_row(3)", "row \"k1, (yo, k2tog) x4, k1\" row \"p\" row \"k\""));
  EXPECT_TRUE(same_fabric("round", 10, "lace.eyelet_row(3)", "row \"k1, (yo, k2tog) x4, k1\" rows(2, \"k\")"));
  // On a wrong-side row it is worked with p2tog, which shows as k2tog on the face.
  EXPECT_TRUE(same_fabric("flat", 10, "row \"k\" lace.eyelet_row()", "row \"k\" row \"p1, (yo, p2tog) x4, p1\""));
  // Worked left to right from the back: k1, yo, k2tog, k1 on the face, read from the left.
  EXPECT_TRUE(same_fabric("flat", 4, "row \"k\" lace.eyelet_row()", "row \"k\" chart [[\n| O / |\n]]"));
}

TEST(ModulesLace, Chevron) {
  const std::string lace_row = "row \"k1, yo, k2, cdd, k2, yo, k1, yo, k2, cdd, k2, yo\"\n";
  EXPECT_TRUE(same_fabric("flat", 16, "lace.chevron(4)", lace_row + "row \"p\"\n" + lace_row + "row \"p\"\n"));
  EXPECT_TRUE(same_fabric("round", 16, "lace.chevron(4)", lace_row + "row \"k\"\n" + lace_row + "row \"k\"\n"));
  // The lace rows are the odd rows of the piece, the right side when flat.
  EXPECT_TRUE(same_fabric("flat", 8, "row \"k\" lace.chevron(2)", "row \"k\" row \"p\" row \"k1, yo, k2, cdd, k2, yo\""));
  for (const auto& k : both)
    EXPECT_TRUE(same_fabric(k, 8, "lace.chevron(2)", "chart [[\n| | | | | | | |\nO | | ^ | | O |\n]]"));
}

TEST(ModulesLace, FeatherAndFan) {
  const std::string fan =
      "row \"k2tog, k2tog, k2tog, yo, k1, yo, k1, yo, k1, yo, k1, yo, k1, yo, k1, k2tog, k2tog, k2tog\"\n";
  EXPECT_TRUE(same_fabric("flat", 18, "lace.feather_and_fan(8)",
                          "for i = 1, 2 do row \"k\" row \"p\" " + fan + " row \"k\" end"));
  EXPECT_TRUE(same_fabric("round", 36, "lace.feather_and_fan(8)",
                          "for i = 1, 2 do row \"k\" row \"k\" " + fan + " row \"p\" end"));
  EXPECT_TRUE(same_fabric("flat", 18, "lace.feather_and_fan(1) lace.feather_and_fan(3)", "lace.feather_and_fan(4)"));
  // Every row keeps the stitch count.
  for (const auto& c : run_with_library("flat", 36, "lace.feather_and_fan(4)").courses) EXPECT_EQ(produced(c), 36);
}

// ---- errors in library calls are at the caller's line ----

struct BadCall {
  const char* knitting;
  int stitches;
  const char* body;     // from line 4
  const char* message;  // exact
};

void PrintTo(const BadCall& call, std::ostream* os) { *os << call.body; }

class ModulesErrors : public ::testing::TestWithParam<BadCall> {};

TEST_P(ModulesErrors, PointAtTheCallersLine) {
  EXPECT_EQ(error_of(GetParam().knitting, GetParam().stitches, GetParam().body), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    ModulesCatalogue, ModulesErrors,
    ::testing::Values(
        BadCall{"round", 12, "ribs.k2p2(2.5)\n", "t.lua:4: ribs.k2p2: rows must be a whole number from 1 up, not 2.5"},
        BadCall{"flat", 12, "row \"k\"\nribs.k1p1(0)\n", "t.lua:5: ribs.k1p1: rows must be a whole number from 1 up, not 0"},
        BadCall{"round", 12, "ribs.garter()\n", "t.lua:4: ribs.garter: rows must be a whole number from 1 up, not nil"},
        BadCall{"round", 12, "ribs.seed(\"4\")\n", "t.lua:4: ribs.seed: rows must be a whole number from 1 up, not \"4\""},
        BadCall{"round", 12, "local function band()\n  ribs.moss(-1)\nend\nband()\n",
                "t.lua:5: ribs.moss: rows must be a whole number from 1 up, not -1"},
        BadCall{"flat", 13, "ribs.k2p2(4)\n", "t.lua:4: ribs.k2p2 needs a multiple of 4 stitches, or of 4 plus 2; 13 are live"},
        BadCall{"flat", 2, "ribs.k2p2(4)\n", "t.lua:4: ribs.k2p2 needs a multiple of 4 stitches, or of 4 plus 2; 2 are live"},
        BadCall{"flat", 1, "ribs.seed(2)\n", "t.lua:4: ribs.seed needs at least 2 stitches; 1 is live"},
        BadCall{"flat", 12, "ribs.rib(4, 0, 2)\n", "t.lua:4: ribs.rib: knits must be a whole number from 1 up, not 0"},
        BadCall{"flat", 12, "ribs.rib(4, 2)\n", "t.lua:4: ribs.rib: purls must be a whole number from 1 up, not nil"},
        BadCall{"flat", 13, "ribs.rib(4, 2, 1)\n", "t.lua:4: ribs.rib(2, 1) needs a multiple of 3 stitches, or of 3 plus 2; 13 are live"},
        BadCall{"flat", 14, "cables.rope(4)\n", "t.lua:4: cables.rope takes a table, e.g. cables.rope{ rows = 12 }, not 4"},
        BadCall{"flat", 14, "cables.rope {}\n", "t.lua:4: cables.rope: rows must be a whole number from 1 up, not nil"},
        BadCall{"flat", 14, "cables.rope { rows = 4, width = 5 }\n", "t.lua:4: cables.rope: width must be 2, 4, 6 or 8, not 5"},
        BadCall{"flat", 14, "cables.rope { rows = 4, crossevery = 2, colour = 1, [1] = 2 }\n",
                "t.lua:4: cables.rope: unknown field(s) [1], colour, crossevery; known fields: cross, cross_every, "
                "purl_border, rows, width"},
        BadCall{"flat", 14, "cables.rope { rows = 4, cross_every = 3 }\n",
                "t.lua:4: cables.rope: cross_every is 3, but flat cables cross on right-side rows only; make it even"},
        BadCall{"flat", 14, "cables.rope { rows = 4, cross = \"left\" }\n",
                "t.lua:4: cables.rope: cross must be \"front\" or \"back\", not \"left\""},
        BadCall{"flat", 14, "cables.rope { rows = 4, purl_border = -1 }\n",
                "t.lua:4: cables.rope: purl_border must be a whole number from 0 up, not -1"},
        BadCall{"round", 13, "cables.rope { rows = 4 }\n",
                "t.lua:4: cables.rope needs a multiple of 6 stitches plus 2 (width 4, purl_border 2); 13 are live"},
        BadCall{"round", 10, "cables.rope { rows = 4, purl_border = 0 }\n",
                "t.lua:4: cables.rope needs a multiple of 4 stitches (width 4, purl_border 0); 10 are live"},
        BadCall{"round", 2, "cables.rope { rows = 4 }\n",
                "t.lua:4: cables.rope needs a multiple of 6 stitches plus 2 (width 4, purl_border 2); 2 are live"},
        BadCall{"flat", 12, "cables.horseshoe { rows = 4, cross = \"front\" }\n",
                "t.lua:4: cables.horseshoe: unknown field(s) cross; known fields: cross_every, purl_border, rows, width"},
        BadCall{"flat", 12, "cables.horseshoe { rows = 4, width = 6 }\n",
                "t.lua:4: cables.horseshoe: width must be 4, 8, 12 or 16, not 6"},
        BadCall{"flat", 12, "lace.chevron(4)\n", "t.lua:4: lace.chevron needs a multiple of 8 stitches; 12 are live"},
        BadCall{"flat", 2, "lace.eyelet_row()\n", "t.lua:4: lace.eyelet_row needs a multiple of 2 stitches, at least 4; 2 are live"},
        BadCall{"flat", 10, "lace.eyelet_row(1.5)\n", "t.lua:4: lace.eyelet_row: rows must be a whole number from 1 up, not 1.5"},
        BadCall{"round", 18, "lace.feather_and_fan(0)\n",
                "t.lua:4: lace.feather_and_fan: rows must be a whole number from 1 up, not 0"},
        BadCall{"round", 20, "lace.feather_and_fan(4)\n",
                "t.lua:4: lace.feather_and_fan needs a multiple of 18 stitches; 20 are live"}),
    [](const ::testing::TestParamInfo<BadCall>& param) { return "call" + std::to_string(param.index); });

// ---- the example patterns ----

TEST(ModulesExamples, ThePatternsUsingTheLibraryRun) {
  for (const char* name : {"rib", "seed", "cable_panel"}) {
    const auto path = fs::path(KNITC_SOURCE_DIR) / "patterns" / (std::string(name) + ".lua");
    const Pattern p = runtime::run_pattern_file(path.string()).pattern;
    EXPECT_LE(p.cast_on, 30) << name;
    EXPECT_LE(p.courses.size(), 30u) << name;
    EXPECT_TRUE(p.bound_off) << name;
    for (const auto& c : p.courses) EXPECT_EQ(produced(c), p.cast_on) << name;
  }
}

}  // namespace
}  // namespace knitc
