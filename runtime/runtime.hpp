// The runtime: runs a pattern script in a sandboxed Lua 5.4 state and returns the
// validated Pattern it describes. The only part of knitc that knows Lua.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "pattern.hpp"

namespace knitc::runtime {

struct Limits {
  std::uint64_t instructions = 200'000'000;  // Lua VM instructions, about a second
  std::size_t memory_bytes = 256u << 20;     // bytes the Lua state may hold at once
};

struct RunOptions {
  Limits limits;
  // Where `require "name"` looks, in order, before the pattern's own lib/ folder and
  // knitc's library (patterns/lib). Nothing else of the file system is reachable.
  std::vector<std::string> module_dirs;
  std::optional<std::int64_t> seed;  // math.random's seed; else pattern{ seed = } or 0
  int max_tucks = 4;                 // tucks stacked on one needle before it is an error
  double max_float_mm = 25.0;        // floats longer than this are warned about
};

// A problem in a pattern script. what() is "file:line: what went wrong; what to do".
class PatternError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunResult {
  Pattern pattern;
  std::vector<std::string> warnings;  // "file:line: ..." each
};

// Runs `source` as the script `file` (the name messages use) and builds its Pattern.
// Throws PatternError for any problem in the script, its limits or its meaning.
RunResult run_pattern(std::string_view source, const std::string& file, const RunOptions& options = {});

// Reads the script at `path` and runs it. Throws std::runtime_error if the file cannot
// be read, PatternError for problems in it.
RunResult run_pattern_file(const std::string& path, const RunOptions& options = {});

// The reference of the pattern language, as Markdown: every verb, stitch and chart
// symbol, generated from the tables that declare them (docs/language.md).
std::string language_reference();

}  // namespace knitc::runtime
