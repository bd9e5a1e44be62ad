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

// Scripts that try to leave the sandbox find nothing there.
TEST(Sandbox, NoFilesProcessesDebugOrBytecode) {
  const std::string start = std::string(header) + "cast_on(4)\nrow \"k\"\n";
  for (const char* attack : {"io.open('/etc/passwd')", "os.execute('true')", "os.time()", "os.clock()",
                             "debug.sethook()", "package.loadlib('x', 'y')",
                             "dofile('/etc/passwd')", "loadfile('/etc/passwd')", "string.dump(print)",
                             "collectgarbage('stop')", ";(''):dump()"}) {
    const std::string message = error_of(start + attack + "\n");
    EXPECT_NE(message.find("t.lua:8: attempt to"), std::string::npos) << attack << " -> " << message;
  }
  // require reaches the pattern library only: "os" is just a module that is not there.
  EXPECT_EQ(error_of(start + "require('os')\n").rfind("t.lua:8: module \"os\" not found", 0), 0u);
  // Binary chunks are refused even through the text-only load.
  // (error(..., 0) gives no position; knitc puts the line in front of every message.)
  EXPECT_EQ(error_of(start + "local f, err = load('\\27Lua') assert(f == nil) error(err, 0)\n"),
            "t.lua:8: attempt to load a binary chunk (mode is 't')");
  // load of text still works, for generated patterns.
  EXPECT_EQ(error_of(start + "assert(load('return 1 + 1')() == 2)\n"), "");
}

TEST(Sandbox, AnEndlessLoopStopsWithinTheInstructionBudget) {
  runtime::Limits limits;
  limits.instructions = 20'000'000;
  const auto t0 = std::chrono::steady_clock::now();
  const std::string message = error_of(std::string(header) + "cast_on(4)\nwhile true do\nend\n", limits);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(message, "t.lua:7: pattern ran too long (over 20 million Lua instructions, counting the work inside library "
                     "calls); look for a loop that never ends");
  EXPECT_LT(seconds, 10.0);  // a guard against a hook that never fires, not a timing test
}

TEST(Sandbox, ATableBombStopsAtTheMemoryCap) {
  runtime::Limits limits;
  limits.memory_bytes = 16u << 20;
  const std::string message =
      error_of(std::string(header) + "cast_on(4)\nlocal t = {}\nfor i = 1, 1e9 do\n  t[i] = {i, i, i}\nend\n", limits);
  EXPECT_EQ(message, "t.lua:9: pattern used more than 16 MiB of memory; look for a table or string that grows without end");
  // A string too long for the sandbox is refused before it is made.
  const std::string strings = error_of(std::string(header) + "local s = string.rep('x', 1 << 30)\n", limits);
  EXPECT_EQ(strings.rfind("t.lua:6: pattern made a string longer than 4 MiB (string.rep of 1.02e+03 MiB)", 0), 0u) << strings;
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
