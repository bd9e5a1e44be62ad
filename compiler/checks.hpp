// Checks of a whole pattern that no single row can make: tucks stacked on one needle,
// floats too long to wear. Plain data in, diagnostics out.
#pragma once

#include <string>
#include <vector>

#include "pattern.hpp"

namespace knitc {

struct Diagnostic {
  SourceLocation where;
  std::string message;  // without the location
  bool error = false;   // else a warning
};

struct CheckLimits {
  int max_tucks = 4;           // tucks held on one needle before it cannot be knitted off
  double max_float_mm = 25.0;  // floats longer than this snag
};

std::vector<Diagnostic> check_pattern(const Pattern& pattern, const CheckLimits& limits);

}  // namespace knitc
