// The command line's options for a printed pattern (`knitc build pattern.txt`): the
// declaration a script would make itself. Meaningless for a script, so refused there.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "runtime.hpp"

namespace knitc::cli {

struct PrintedArgs {
  knitc::runtime::PrintedOptions options;
  std::string gauge;     // "22x30", as given
  std::string knitting;  // "flat", "round" or "" (from the text)
};

// --cast-on, --gauge, --weight, --knitting, --selvedge on `cmd`.
void add_printed_options(CLI::App* cmd, PrintedArgs& a);

// Settles the options for the pattern at `path`: nothing when they are good, else the
// message (exit 2): a printed option given for a script, a gauge or weight not known.
std::optional<std::string> settle_printed_options(const CLI::App* cmd, const std::string& path, PrintedArgs& a);

}  // namespace knitc::cli
