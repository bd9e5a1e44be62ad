// How patterns write each stitch: its written spellings, chart symbol, Lua name, whether
// a count follows it, and its line in the reference. What a stitch is lives in the stitch
// table (compiler/stitches); these are the pattern language's words for it, read by the
// parsers, the default legend, the Lua globals, `knitc chart`, the reference and the hints.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "stitches/stitches.hpp"

namespace knitc::language {

struct StitchWords {
  std::string_view aliases;     // other written spellings than the name, separated by '|'
  std::string_view symbol;      // chart symbol (the name is accepted in charts too)
  std::string_view identifier;  // the Lua global of the plain form, e.g. course { k, p }; may be empty
  bool counted = false;         // takes a repeat count: k2, p3, yo2, sl2 wyif
  std::string_view summary;     // one line for the reference docs
};

// The words of stitch `id` (every stitch of the table has them).
const StitchWords& words(StitchId id);

// The stitch said in full, as its summary opens ("knit two together" for k2tog): the
// summary up to its first colon, else the stitch's name.
std::string_view long_name(StitchId id);

// The stitch a name or alias spells, case-insensitive.
std::optional<StitchId> find_stitch(std::string_view name_or_alias);

// The known name or alias nearest to `word` (edit distance), for "did you mean" hints.
std::string nearest_stitch_name(std::string_view word);

// Calls visit(spelling) for the stitch's name, then each of its aliases.
template <typename Visit>
void for_each_spelling(StitchId id, Visit visit) {
  visit(stitch(id).name);
  std::string_view rest = words(id).aliases;
  while (!rest.empty()) {
    const auto bar = rest.find('|');
    visit(rest.substr(0, bar));
    rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
  }
}

// `s` in lower case (ASCII letters only, as the pattern language's spellings are): the one
// lowercasing of the written rows, knitspeak, the spellings and the declarations.
std::string lower(std::string_view s);

// Edit distance (Levenshtein, case-insensitive), for hints.
int edit_distance(std::string_view a, std::string_view b);

}  // namespace knitc::language
