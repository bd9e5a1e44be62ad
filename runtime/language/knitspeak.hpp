// Printed pattern text, as a book or Stitch Maps prints it, read line by line into the
// rows it asks for, in working order. Pure C++ (no Lua), so it can be fuzzed alone.
//
//   Row 1 (RS): K1, *p1, k1; rep from *.      a row, its side said or not
//   Rows 2 and 4: Purl.                        one text for several rows
//   Rnds 3, 5, and 7-9: Knit.                  lists and ranges; Row, Rnd, Round alike
//   Rows 5-8: Repeat rows 1-4.                 rows given as earlier ones
//   Repeat rows 3-6.                           those rows once more, where the line stands
//   Row 9: k2, yo, k2tog, k1 (6 sts).          a stated stitch count, checked
//   k2, p2 to end of round.                    an unnumbered line of stitches: a row
//   1st row.—K 2, p 2.  3rd row: As 1st row.  vintage labels, several to a paragraph
//   Row 2 (and every WS row): purl.            a text for every row of that side not given
//   C4Bp: slip 2 sts to cn, hold to back, k2, p2 from cn.   a glossary line (glossary.hpp)
// Rows are worked in number order; a heading, a note or any other line that is not a row
// is skipped with a warning. Bullets ("-", "•") and full stops are tolerated.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/glossary.hpp"
#include "pattern.hpp"

namespace knitc::language {

struct KnitspeakRow {
  int line = 0;                       // 0-based line of the block it comes from
  int number = 0;                     // its printed number, 0 for an unnumbered line
  std::string text;                   // the written instructions, for parse_row
  std::optional<Side> side;           // "(RS)" / "(WS)" as printed
  std::optional<int> stitches_after;  // "(14 sts)": the live stitches the row leaves
  bool repeat = false;                // worked again by a "Repeat rows ..." line
};

struct KnitspeakNote {
  int line = 0;  // 0-based
  std::string message;
};

struct Knitspeak {
  std::vector<KnitspeakRow> rows;     // in working order, repeats written out; the
                                      // glossary's abbreviations in the names they stand for
  std::vector<KnitspeakNote> skipped; // lines that are not rows: the warnings
  std::vector<GlossaryEntry> glossary;  // the abbreviations the text defines
};

// Reads a block. `yarn_ids` as for parse_row (an unnumbered line is a row only if it
// parses as one). A problem (a row given twice, a missing row, a repeat of rows not yet
// given) is a KnitspeakNote naming its line.
std::variant<Knitspeak, KnitspeakNote> read_knitspeak(std::string_view block, std::span<const std::string> yarn_ids);

}  // namespace knitc::language
