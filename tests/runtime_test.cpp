// The runtime: a script becomes a Pattern; problems become located messages; the
// sandbox stops scripts that reach outside it or run away.
#include <chrono>

#include <gtest/gtest.h>

#include "support.hpp"

namespace knitc {
namespace {

using runtime::PatternError;

const char* header = R"(pattern {
  name  = "jersey",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 },
  yarns = { A = { diameter = 1.0, color = "#D9C8A9" } },
}
)";

// The message a script fails with, or "" if it runs.
std::string error_of(const std::string& source, const runtime::Limits& limits = {}) {
  try {
    runtime::RunOptions options;
    options.limits = limits;
    runtime::run_pattern(source, "t.lua", options);
  } catch (const PatternError& e) {
    return e.what();
  }
  return "";
}

TEST(Runtime, JerseyScriptBecomesAPattern) {
  const Pattern p = runtime::run_pattern(std::string(header) + "cast_on(20)\nrows(24, \"k\")\n", "j.lua").pattern;
  EXPECT_EQ(p.name, "jersey");
  EXPECT_DOUBLE_EQ(p.gauge.loop_width, 4.0);
  EXPECT_DOUBLE_EQ(p.gauge.loop_height, 4.2);
  EXPECT_DOUBLE_EQ(p.gauge.thickness, 2.0);
  ASSERT_EQ(p.yarns.size(), 1u);
  EXPECT_EQ(p.yarns[0].id, "A");
  EXPECT_EQ(p.yarns[0].color, "#d9c8a9");
  EXPECT_EQ(p.knitting, Knitting::round);
  EXPECT_EQ(p.cast_on, 20);
  ASSERT_EQ(p.courses.size(), 24u);
  for (const auto& c : p.courses) {
    EXPECT_EQ(c.ops.size(), 20u);
    EXPECT_EQ(c.where.file, "j.lua");
    EXPECT_EQ(c.where.line, 7);
  }
}

TEST(Runtime, GaugePerTenCentimetres) {
  const Pattern p = runtime::run_pattern(R"(pattern { gauge = { stitches = 20, rows = 25 },
    yarns = { B = { diameter = 1.5 }, A = { diameter = 2.0, color = "#fff" } } }
cast_on(4) row "k2" for i = 1, 3 do row "k" end)", "g.lua").pattern;
  EXPECT_DOUBLE_EQ(p.gauge.loop_width, 5.0);
  EXPECT_NEAR(p.gauge.course_spacing(), 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.gauge.thickness, 4.0);  // two of the thickest yarn
  ASSERT_EQ(p.yarns.size(), 2u);
  EXPECT_EQ(p.yarns[0].id, "A");  // sorted, whatever the table order
  EXPECT_EQ(p.yarns[0].color, "#ffffff");
  EXPECT_EQ(p.yarns[1].color, "#d9c8a9");
  EXPECT_EQ(p.courses.size(), 4u);
}

struct BadScript {
  const char* body;      // after the header, which is 5 lines
  const char* message;   // exact
};

void PrintTo(const BadScript& script, std::ostream* os) { *os << script.body; }

class RuntimeErrors : public ::testing::TestWithParam<BadScript> {};

TEST_P(RuntimeErrors, NameTheFileLineAndWhatToDo) {
  EXPECT_EQ(error_of(std::string(header) + GetParam().body), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, RuntimeErrors,
    ::testing::Values(
        BadScript{"cast_on(10)\nrows(2, \"k3\")\n",
                  "t.lua:7: row \"k3\" uses 3 stitches per repeat, which does not come out on 10 live stitches "
                  "(1 left over); change the repeat or the stitch count"},
        BadScript{"cast_on(2)\nrow \"k3\"\n",
                  "t.lua:7: row \"k3\" uses 3 stitches per repeat, which does not come out on 2 live stitches "
                  "(1 missing); change the repeat or the stitch count"},
        BadScript{"cast_on(4)\nrow \"k, x\"\n",
                  "t.lua:7: unknown stitch 'x' in \"k, x\"; this version of knitc knows k (knit)"},
        BadScript{"rows(2, \"k\")\n", "t.lua:6: no live stitches; call cast_on(n) first"},
        BadScript{"cast_on(2.5)\n", "t.lua:6: cast_on's stitch count must be a whole number, not 2.5"},
        BadScript{"cast_on(0)\n", "t.lua:6: cast_on's stitch count is 0; it must be from 1 to 100000"},
        BadScript{"cast_on(4)\ncast_on(4)\n", "t.lua:7: cast_on was already called at line 6"},
        BadScript{"cast_on(4)\n", "t.lua:6: the pattern has no courses; add some, e.g. rows(10, \"k\")"},
        BadScript{"pattern { gauge = {}, yarns = {} }\n", "t.lua:6: pattern{} was already given at line 1; give it once"},
        BadScript{"cast_on(4)\nrow \"k,,k\"\n", "t.lua:7: row \"k,,k\" has an empty stitch between commas"},
        BadScript{"cast_on(4)\nrow(\"\")\n", "t.lua:7: row text is empty; give stitches such as \"k\""},
        BadScript{"cast_on(4)\nrows(1e9, \"k\")\n", "t.lua:7: rows' count is 1000000000; it must be from 1 to 100000"},
        BadScript{"cast_on(4)\nlocal x = nil + 1\n",
                  "t.lua:7: attempt to perform arithmetic on a nil value"},
        BadScript{"cast_on(4)\nerror({})\n",
                  "t.lua:7: error raised with a table value instead of a message; pass error() a string"},
        BadScript{"cast_on(4)\nrow \"k\"\nfor\n", "t.lua:9: <name> expected near <eof>"}),
    [](const ::testing::TestParamInfo<BadScript>& param) { return "script" + std::to_string(param.index); });

TEST(RuntimeErrors, PatternDeclarationProblems) {
  auto with = [](const std::string& decl) { return error_of(decl + "\ncast_on(4)\nrow \"k\"\n"); };
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 30 } }"),
            "t.lua:1: pattern{} needs yarns, e.g. yarns = { A = { diameter = 1.0, color = \"#d9c8a9\" } }");
  EXPECT_EQ(with("pattern { yarns = { A = { diameter = 1 } } }"),
            "t.lua:1: pattern{} needs a gauge, e.g. gauge = { stitches = 22, rows = 30 } (per 10 cm)");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1 } }, colour = 1, bogus = 2 }"),
            "t.lua:1: unknown field 'bogus' in pattern{}; known fields: name, gauge, yarns, knitting");
  EXPECT_EQ(with("pattern { gauge = { stitches = -3, rows = 30 }, yarns = { A = { diameter = 1 } } }"),
            "t.lua:1: gauge.stitches is -3 per 10 cm; it must be more than 0 per 10 cm and at most 200 per 10 cm");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, loop_height = 3 }, yarns = { A = { diameter = 1 } } }"),
            "t.lua:1: gauge mixes stitches/rows with loop_width/loop_height; give one pair or the other");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 0/0 }, yarns = { A = { diameter = 1 } } }"),
            "t.lua:1: gauge.rows is NaN; it must be more than 0 per 10 cm and at most 300 per 10 cm");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 0 } } }"),
            "t.lua:1: yarns.A.diameter is 0 mm; it must be more than 0 mm and at most 30 mm");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1, color = \"red\" } } }"),
            "t.lua:1: yarns.A.color is \"red\"; give a CSS hex colour such as \"#d9c8a9\"");
  EXPECT_EQ(with("pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }"),
            "t.lua:1: knitting = \"flat\" is not supported yet; knit in the round (the default)");
  EXPECT_EQ(error_of("cast_on(4)\n"), "t.lua:1: cast_on comes before pattern{}; declare the pattern first");
  EXPECT_EQ(error_of("local x = 1\n"),
            "t.lua:1: the script never calls pattern{}; start it with pattern { name = ..., gauge = ..., yarns = ... }");
}

// Scripts that try to leave the sandbox find nothing there.
TEST(Sandbox, NoFilesProcessesDebugOrBytecode) {
  const std::string start = std::string(header) + "cast_on(4)\nrow \"k\"\n";
  for (const char* attack : {"io.open('/etc/passwd')", "os.execute('true')", "os.time()", "os.clock()",
                             "debug.sethook()", "require('os')", "package.loadlib('x', 'y')",
                             "dofile('/etc/passwd')", "loadfile('/etc/passwd')", "string.dump(print)",
                             "collectgarbage('stop')", ";(''):dump()"}) {
    const std::string message = error_of(start + attack + "\n");
    EXPECT_NE(message.find("t.lua:8: attempt to"), std::string::npos) << attack << " -> " << message;
  }
  // Binary chunks are refused even through the text-only load.
  EXPECT_EQ(error_of(start + "local f, err = load('\\27Lua') assert(f == nil) error(err, 0)\n"),
            "attempt to load a binary chunk (mode is 't')");
  // load of text still works, for generated patterns.
  EXPECT_EQ(error_of(start + "assert(load('return 1 + 1')() == 2)\n"), "");
}

TEST(Sandbox, AnEndlessLoopStopsWithinTheInstructionBudget) {
  runtime::Limits limits;
  limits.instructions = 20'000'000;
  const auto t0 = std::chrono::steady_clock::now();
  const std::string message = error_of(std::string(header) + "cast_on(4)\nwhile true do\nend\n", limits);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(message, "t.lua:7: pattern ran too long (over 20 million Lua instructions); look for a loop that never ends");
  EXPECT_LT(seconds, 10.0);  // a guard against a hook that never fires, not a timing test
}

TEST(Sandbox, ATableBombStopsAtTheMemoryCap) {
  runtime::Limits limits;
  limits.memory_bytes = 16u << 20;
  const std::string message =
      error_of(std::string(header) + "cast_on(4)\nlocal t = {}\nfor i = 1, 1e9 do\n  t[i] = {i, i, i}\nend\n", limits);
  EXPECT_EQ(message, "t.lua:9: pattern used more than 16 MiB of memory; look for a table that grows without end");
  const std::string strings = error_of(std::string(header) + "local s = string.rep('x', 1 << 30)\n", limits);
  EXPECT_EQ(strings.rfind("t.lua:", 0), 0u) << strings;
  EXPECT_NE(strings.find("MiB of memory"), std::string::npos) << strings;
}

TEST(Sandbox, DeepRecursionStopsCleanly) {
  const std::string message = error_of(std::string(header) + "local function f(n) return 1 + f(n + 1) end\nf(1)\n");
  EXPECT_NE(message.find("t.lua:6: stack overflow"), std::string::npos) << message;
}

TEST(Sandbox, RandomNumbersAreTheSameOnEveryRun) {
  const std::string script = std::string(header) +
                             "cast_on(4)\nfor i = 1, 3 do if math.random(1, 1000) > 0 then row \"k\" end end\n"
                             "error(tostring(math.random(1, 1000000)), 0)\n";
  const std::string first = error_of(script);
  EXPECT_EQ(first, error_of(script));
  EXPECT_FALSE(first.empty());
}

}  // namespace
}  // namespace knitc
