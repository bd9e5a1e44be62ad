// Charts: a block of text drawn as the fabric looks from the face, one line per row, the
// last line row 1 (worked first). Pure C++ (no Lua), so it can be fuzzed alone.
//
// Each cell is a legend symbol; symbols may be written with or without spaces between
// them ("| | . ." or "||.."), the longest symbol that matches wins, and a cable's name
// may be followed by '-' to draw its width ("C4F----"), as `knitc chart` prints it.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/written.hpp"

namespace knitc::language {

struct LegendEntry {
  std::string symbol;
  Worked worked;  // the stitch, and its yarn (-1: the current yarn)
};

// Symbols, longest first when matching. The default legend holds each stitch's chart
// symbol and its names.
struct Legend {
  std::vector<LegendEntry> entries;
  // Adds or replaces a symbol. Returns false for a symbol that is empty or holds
  // whitespace.
  bool set(const std::string& symbol, Worked worked);
  const LegendEntry* match(std::string_view text) const;  // the longest entry text starts with
};

Legend default_legend();

struct ChartRow {
  std::vector<Worked> cells;  // face view, left to right
  int line = 0;               // the row's line within the chart text, 0 for the first line
};

struct ChartError {
  int line = 0;  // within the chart text, 0 for the first line
  std::string message;
};

// Rows bottom first (row 1 first). Blank lines are skipped.
std::variant<std::vector<ChartRow>, ChartError> parse_chart(std::string_view text, const Legend& legend);

// The pattern's stitch chart as `knitc chart` prints it: one line per course, top course
// first, symbols from the default legend (a cable drawn across its width), each row's
// number on the side it is read from (right for right-side rows, left for wrong-side
// rows); yarn ids after each row when the pattern changes yarn.
std::string chart_text(const Pattern& pattern);

// A stitch's cell as chart_text draws it: its chart symbol, a cable's name drawn across
// its width ("C4F----" spans 4 cells of "x " each, less the last space).
std::string chart_cell(StitchId id);

}  // namespace knitc::language
