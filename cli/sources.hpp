// The file a knitc command is given, read into a Pattern whatever it holds: a pattern
// script (.lua), a knitout machine program (.k, .knitout, or any file that starts
// ";!knitout-"), else a printed pattern.
#pragma once

#include <string>

#include "runtime.hpp"

namespace knitc::cli {

// The largest knitout program knitc reads: a garment's program is a few MB.
inline constexpr std::size_t max_knitout_bytes = 64u << 20;

bool is_knitout(const std::string& path);

// Throws runtime::PatternError ("file:line: ...") for a problem in the file, whatever
// its kind, and runtime::FileError when it cannot be read.
runtime::RunResult read_pattern(const std::string& path, const runtime::PrintedOptions& printed, const runtime::RunOptions& run);

}  // namespace knitc::cli
