// A printed pattern's glossary: the abbreviations it defines for itself ("C4Bp: slip 2
// sts to cn, hold to back, k2, p2 from cn", "wrn = wool round needle"). A definition
// knitc can read is a stitch it knows by another name, and the pattern's rows are read
// with the abbreviation standing for that name; one it cannot read is kept, so a row that
// uses it is refused with the definition quoted and a hint to declare it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace knitc::language {

// A glossary's bounds: an abbreviation's bytes ("sel s", "C4Bpk", "Front Cross"), the
// bytes of a definition read, and the abbreviations one pattern or block may define.
inline constexpr std::size_t longest_abbreviation = 20;
inline constexpr std::size_t longest_definition = 2000;
inline constexpr std::size_t max_glossary = 200;

struct GlossaryEntry {
  std::string abbreviation;          // as printed, "C4Bp"
  int line = 0;                      // 0-based line of the block
  std::string definition;            // as printed, after the separator
  std::optional<std::string> means;  // what it stands for, as a row's text, if read
  bool known = false;                // an abbreviation knitc reads already: the glossary explains it
};

// The entry a line defines ("ABBR: ...", "ABBR = ...", "ABBR - ...", also after a heading,
// "Notes: B2 = knit 2 sts at each end"), or nothing when the line is not of that form.
// A definition is read as a stitch's name, a cross in words, or a few stitches ("knit 2
// stitches on each end for border" is k2).
std::optional<GlossaryEntry> read_glossary_line(std::string_view line, int number);

// A cable's working in words, as the stitch table names it: "slip 2 sts to cn, hold in
// back, k2, p2 from cn" is "2/2 RPC"; nothing when the words are not a cross knitc has.
std::optional<std::string> cross_in_words(std::string_view definition);

// `text` with every abbreviation the glossary reads replaced by the name it stands for
// (whole words, any case, the longest first).
std::string with_glossary(std::string_view text, std::span<const GlossaryEntry> glossary);

// `text` with each cross described in brackets where it is worked, "Front Cross (slip next
// 3 sts to cn and hold in front, k3, k3 from cn)", written as its name ("3/3 LC"); the
// words before the bracket back to the last comma are its name in the pattern.
std::string with_crosses_in_words(std::string_view text);

// The first entry the glossary could not read that `text` uses (a whole word), or null.
const GlossaryEntry* unread_abbreviation_in(std::string_view text, std::span<const GlossaryEntry> glossary);

}  // namespace knitc::language
