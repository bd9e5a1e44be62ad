// The runtime: runs a pattern script in a sandboxed Lua 5.4 state and returns the
// validated Pattern it describes. The only part of knitc that knows Lua.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "pattern.hpp"

namespace knitc::runtime {

struct Limits {
  std::uint64_t instructions = 200'000'000;  // Lua VM instructions, about a second
  std::size_t memory_bytes = 256u << 20;     // bytes the Lua state may hold at once
};

// A problem in a pattern script. what() is "file:line: what went wrong; what to do".
class PatternError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `source` as the script `file` (the name messages use) and builds its Pattern.
// Throws PatternError for any problem in the script, its limits or its meaning.
Pattern run_pattern(std::string_view source, const std::string& file, const Limits& limits = {});

// Reads the script at `path` and runs it. Throws std::runtime_error if the file cannot
// be read, PatternError for problems in it.
Pattern run_pattern_file(const std::string& path, const Limits& limits = {});

}  // namespace knitc::runtime
