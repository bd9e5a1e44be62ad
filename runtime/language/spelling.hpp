// Spellings as printed: the one normalisation of a pattern's text, shared by the written
// rows, the charts' legends and knitspeak. Vintage, British and hand-typed patterns write
// one abbreviation many ways ("K 2 tog", "p.s.s.o.", "sl1pw", "k2tbl", "with yarn in
// front", "rep.", "×"); these functions turn them into the spellings of words.cpp, and
// refuse a spelling that could mean more than one stitch rather than pick one.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "stitches/stitches.hpp"

namespace knitc::language {

// A row's text as the parsers read it. Typography becomes ASCII (curly quotes, dashes, the
// × of "× 3", non-breaking spaces); prose modifiers become their abbreviations ("with yarn
// in front" wyif, "purlwise" pwise, "through the back loop" tbl, "together" tog, "pass the
// slipped stitch over" psso); dots inside or after an abbreviation go ("p.s.s.o.", "rep.",
// "sl. 1"), while a full stop between two instructions becomes a comma ("k2. P2"); and
// "ending with" before the stitches that close a repeated row becomes a comma. Case is
// kept (yarn ids are case-sensitive). normalise(normalise(t)) == normalise(t).
std::string normalise(std::string_view text);

// Only the typography of normalise(): curly quotes, dashes, the \u00d7 of times and
// non-breaking spaces as ASCII. Knitspeak reads its labels ("1st row.\u2014K 2") through it.
std::string typography_as_ascii(std::string_view text);

// A stitch read from the words of one item of a row (no commas between them).
struct Reading {
  StitchId stitch = 0;
  int count = 1;                // "p5": 5; 1 when no count is written
  bool count_written = false;   // a count was written on it ("k1", "sl 1")
  bool count_too_large = false; // a count past the language's largest (the caller says so)
};

// A spelling that means one of several stitches: refused, its candidates named.
struct Ambiguous {
  std::string written;
  std::string why;  // "a lifted increase (m1) in modern patterns, a yarn over in vintage ones"
  std::vector<std::string> candidates;
};

// Reads `words` (already normalised) as one stitch: the exact spelling of a name or an
// alias first; then the same letters and digits with spaces, dots and hyphens squeezed out
// ("K 2 tog", "Y O", "sl1-k1-psso"); then a count run into it ("p 5", "sl1pw", "k2tbl",
// "sl5wyif"). Nothing when it spells no stitch.
std::variant<std::monostate, Reading, Ambiguous> read_stitch(std::span<const std::string_view> words);
std::variant<std::monostate, Reading, Ambiguous> read_stitch(std::string_view written);

// The message for an ambiguous spelling: "'inc' could mean ...: write kfb, m1 or yo".
std::string ambiguous_message(const Ambiguous& a);

// The spellings refused as ambiguous, with their candidates, for the reference.
struct AmbiguousSpelling {
  std::string_view written;     // as a knitter writes it
  std::string_view candidates;  // names of the stitch table, separated by '|'
  std::string_view why;
};
std::span<const AmbiguousSpelling> ambiguous_spellings();

// The prose phrases normalise() abbreviates ("with yarn in front" wyif), for the reference.
// An abbreviation of "," closes a repeated row ("ending k1").
struct ProsePhrase {
  std::string_view phrase;
  std::string_view abbreviation;
};
std::span<const ProsePhrase> prose_phrases();

}  // namespace knitc::language
