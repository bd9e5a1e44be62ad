// libFuzzer target for the whole runtime: the input chooses a Lua script, made of the
// pattern's verbs called with hostile arguments (wrong types, huge and odd numbers,
// strings with NUL and escape bytes, tables whose metamethods call verbs, loop, yield or
// lie about their length), library calls that loop or catch, and control flow around
// them. The script runs under a small budget (5 million instructions, 64 MiB, 2 s); it
// must end with a Pattern or a PatternError whose message is located and printable, and
// a Pattern must be one the compiler accepts (its chart drawn, its layout made).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

#include "layout/layout.hpp"
#include "runtime.hpp"
#include "language/chart.hpp"
#include "writers/writers.hpp"

namespace {

using namespace knitc;

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "fuzz_runtime: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  __builtin_trap();
}

const char* const numbers[] = {"0", "1", "2", "3", "4", "8", "-1", "2.5", "1e9", "2^31", "2^53", "2^63", "math.huge",
                               "-math.huge", "0/0", "math.mininteger", "math.maxinteger", "100000", "100001", "1e308"};
const char* const texts[] = {
    "\"k\"", "\"p\"", "\"k2, p2\"", "\"k2tog, yo\"", "\"*k1, p1; rep from *\"", "\"k to end\"", "\"(k1, p1) x3\"",
    "\"C4F\"", "\"sl1 wyif\"", "\"k1 below\"", "\"yo, k2tog, ssk\"", "\"k\\0p\"", "\"\\27[2J\"", "\"\"", "\"k B\"",
    "(\"k, \"):rep(2000)", "(\"k\"):rep(100000)", "\"knit the knit sts and purl the purl sts\"", "\"m1, k\"",
    "\"[k1, p1] to last st, k1\"", "\"k2 B, p2\"", "\"cdd\"", "\"2/2 RC\"", "\"brk\""};
const char* const blocks[] = {
    "[[\nRow 1 (RS): K1, *p1, k1; rep from *.\nRow 2: P1, *k1, p1; rep from *.\n]]",
    "[[\nRows 1-4: Knit.\nRepeat rows 1-4.\n]]", "[[\nRow 1: k\nRows 2-100000000: p\n]]", "[[\nRow 1: k\nRows 2-: p\n]]",
    "[[\nA heading\nRow 1: k (8 sts)\n]]", "[[\nRow 1 (WS): p\nRow 2: k\n]]", "[[\nRow 2: k\n]]",
    "[[\nRow 1: k\nRows 2-99999: Repeat rows 1-99998.\nRepeat rows 1-99999.\n]]", "[[\n]]", "[[\nk2, p2 to end.\n]]"};
const char* const charts[] = {"[[\n| | . .\n| | . .\n]]", "[[\n# # #\n]]", "[[\n|\n]]", "[[\n/ o |\n]]", "[[\n]]",
                              "{ [[\n| .\n]], rep = 3 }", "{ [[\n# .\n]], legend = { [\"#\"] = \"p\" } }",
                              "{ [[\n| |\n]], rep = 100000 }"};
const char* const tables[] = {
    "{ k, p }", "{ k, p, rep = 2 }", "{ k, { p, yarn = \"A\" } }", "{ k, { p, yarn = \"Z\" } }", "{}", "{ 1, 2 }",
    "setmetatable({}, { __len = function() return 1e8 end, __index = type })",
    "setmetatable({ k }, { __len = function() rows(1, \"k\") return 1 end })",
    "setmetatable({}, { __len = function() return 4 end, __index = function() return \"k\" end })",
    "setmetatable({}, { __index = function(t, i) pattern {} end })",
    "setmetatable({ k }, { __len = function() coroutine.yield() return 1 end })",
    "setmetatable({}, { __len = function() while true do end end })", "{ [\"#\"] = \"k\" }",
    "{ [\"#\"] = { \"p\", yarn = \"A\" } }", "{ [\"\"] = \"k\" }", "{ [\"a b\"] = \"k\" }"};
const char* const pattern_heads[] = {
    "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }",
    "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" }, B = { diameter = 1 } }, knitting = \"flat\" }",
    "pattern { gauge = { loop_width = 4, loop_height = 4.2 }, yarns = { A = { diameter = 1, section = \"plied\" } } }",
    "pattern { gauge = { stitches = 0/0, rows = 30 }, yarns = { A = { weight = \"dk\" } } }",
    "pattern { gauge = setmetatable({ stitches = 22 }, { __index = function() cast_on(4) return 30 end }), yarns = { A = { weight = \"dk\" } } }",
    "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { [\"A\\0B\"] = { weight = \"dk\" } } }",
    "pcall(pattern, { gauge = { stitches = 22 }, yarns = { A = { weight = \"dk\" }, B = { weight = \"dk\" } } })",
    "pattern(setmetatable({}, { __index = function() while true do end end }))", ""};
const char* const attacks[] = {
    "while true do end", "pcall(function() while true do end end)", "local t = {} while true do t[#t + 1] = {} end",
    "local s = ('a'):rep(40) s:find(('a*'):rep(40) .. 'b')", "string.rep('', 2^50)", "string.rep('x', 2^40)",
    "coroutine.wrap(function() while true do end end)()", "setmetatable({}, { __gc = function() end })",
    "for i = 1, 1e6 do coroutine.resume(coroutine.create(print)) end", "local s = 'x' while true do s = s .. s end",
    "error(setmetatable({}, { __tostring = error }))", "error(('\\27'):rep(100000))", "coroutine.yield()",
    "local t = setmetatable({}, { __index = function(t, k) return t[k] end }) local _ = t.x",
    "table.concat(setmetatable({}, { __len = function() return 2^40 end, __index = type }))",
    "table.sort({ 3, 1, 2 }, function(a, b) return true end)", "for k in pairs({ [{}] = 1 }) do end",
    "load(('x = 1 '):rep(1000))()", "do local x <close> = setmetatable({}, { __close = function() error('c') end }) end",
    "print(('\\27[31m'):rep(10))", "require 'ribs'", "require 'no_such'", "require 'ribs\\0x'", "local r = require 'ribs' r.k2p2(4)",
    "local c = require 'cables' c.rope(4)", "live()", "knitting()", "row_number()"};

struct Script {
  FuzzedDataProvider& in;
  std::string out;

  template <std::size_t N>
  const char* pick(const char* const (&from)[N]) { return from[in.ConsumeIntegralInRange<std::size_t>(0, N - 1)]; }

  std::string argument() {
    switch (in.ConsumeIntegralInRange(0, 4)) {
      case 0: return pick(numbers);
      case 1: return pick(texts);
      case 2: return pick(tables);
      case 3: {  // raw bytes from the input, as a Lua string
        std::string s = in.ConsumeRandomLengthString(40), lua = "\"";
        for (unsigned char c : s) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\%u", c);
          lua += escape;
        }
        return lua + "\"";
      }
      default: return "nil";
    }
  }

  void statement(int depth) {
    switch (in.ConsumeIntegralInRange(0, 17)) {
      case 0: out += "cast_on(" + argument() + ")\n"; break;
      case 1: out += std::string("row(") + pick(texts) + ")\n"; break;
      case 2: out += std::string("rows(") + pick(numbers) + ", " + pick(texts) + ")\n"; break;
      case 3: out += std::string("course ") + pick(tables) + "\n"; break;
      case 4: out += std::string("chart ") + pick(charts) + "\n"; break;
      case 5: out += std::string("knitspeak ") + pick(blocks) + "\n"; break;
      case 6: out += std::string("legend ") + pick(tables) + "\n"; break;
      case 7: out += "yarn(" + argument() + ")\n"; break;
      case 8: out += "bind_off()\n"; break;
      case 9: out += std::string(pick(attacks)) + "\n"; break;
      case 10: out += "pcall(" + std::string(in.ConsumeBool() ? "row" : "course") + ", " + argument() + ")\n"; break;
      case 11:
        if (depth < 3) {
          out += "for i = 1, " + std::string(pick(numbers)) + " do\n";
          statement(depth + 1);
          out += "end\n";
        }
        break;
      case 12:
        if (depth < 3) {
          out += "coroutine.wrap(function()\n";
          statement(depth + 1);
          out += "end)()\n";
        }
        break;
      case 13:
        if (depth < 3) {
          out += "pcall(function()\n";
          statement(depth + 1);
          out += "end)\n";
        }
        break;
      case 14: out += std::string(pick(pattern_heads)) + "\n"; break;
      case 15: out += "rows(" + argument() + ", " + argument() + ")\n"; break;
      case 16: out += "course { " + argument() + ", " + argument() + " }\n"; break;
      default: out += "rows(2, \"k\")\n"; break;
    }
  }
};

bool printable(const std::string& s) {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  Script script{in, ""};
  script.out += std::string(script.pick(pattern_heads)) + "\n";
  if (in.ConsumeBool()) script.out += "cast_on(" + std::string(script.pick(numbers)) + ")\n";
  const int statements = in.ConsumeIntegralInRange(1, 12);
  for (int i = 0; i < statements && in.remaining_bytes() > 0; ++i) script.statement(0);

  runtime::RunOptions options;
  options.limits.instructions = 5'000'000;
  options.limits.memory_bytes = 64u << 20;
  options.limits.seconds = 2.0;
  try {
    const runtime::RunResult result = runtime::run_pattern(script.out, "fuzz.lua", options);
    for (const auto& w : result.warnings) {
      if (!printable(w)) violated("a warning that is not printable: " + w);
    }
    const Pattern& p = result.pattern;
    (void)language::chart_text(p);
    std::uint64_t loops = static_cast<std::uint64_t>(p.cast_on);
    for (const Course& c : p.courses) loops += c.ops.size();
    if (loops <= 20'000) {
      try {
        (void)layout::lay_out(p);
      } catch (const std::invalid_argument& e) {
        violated(std::string("the runtime accepted a pattern the layout refuses: ") + e.what() + "\n" + script.out);
      }
    }
  } catch (const runtime::PatternError& e) {
    // "file:line: ...": the pattern's own line, or a library module's.
    const std::string message = e.what();
    const std::size_t colon = message.find(':');
    std::size_t digits = colon == std::string::npos ? 0 : colon + 1;
    while (digits < message.size() && message[digits] >= '0' && message[digits] <= '9') ++digits;
    if (colon == std::string::npos || colon == 0 || digits == colon + 1 || message[colon + 1] == '0' ||
        message.compare(digits, 2, ": ") != 0 || message.find('\n') < colon)
      violated("an error without its line: " + message + "\n" + script.out);
    if (!printable(message)) violated("an error that is not printable: " + message);
    if (message.size() > 4096) violated("an error longer than 4 KiB");
  }
  return 0;
}
