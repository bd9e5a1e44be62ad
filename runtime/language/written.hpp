// Written instructions: the text of one row as a knitter writes it, parsed and then
// worked across the live stitches. Pure C++ (no Lua), so it can be fuzzed alone.
//
//   k2, p2                                   repeats across the row until the stitches are used
//   *k2, p2; rep from *                      the same, said explicitly ("to end", "across")
//   k1, *p1, k1; rep from *                  fixed stitches before the repeat
//   *k2, p2; rep from * to last 2 sts, k2    and after it
//   (k2, p2) x6   [k2, p2] 6 times   (k1, p1) twice
//   sl1 wyif, k2tog, C4F, yo2, k2 B          names from the stitch table, counts, a yarn id
//   k1, (p2, k2) to 3 sts before end, p2, k1 an open repeat; also "k to end", "p to last st"
//   *k1, yo, k2; repeat from *.              printed forms: "repeat", a comma before it
//   sl1, k2tog, psso                         passing over, as the stitch it makes (sk2p)
//   knit the knit sts and purl the purl sts  every stitch as it shows
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/words.hpp"
#include "pattern.hpp"

namespace knitc::language {

// The largest count a text may give a stitch or group (k100000, (k, p) x100000).
inline constexpr int max_count = 100'000;

// A problem in a text, without its location (the caller knows the file and line).
struct TextError {
  std::string message;
};

// One stitch in working order, with the yarn it is worked in (-1: the current yarn).
struct Worked {
  StitchId stitch = 0;
  int yarn = -1;
  // An edge stitch ("edge st", "selvedge st", "sel st"): k here, until the work (which
  // knows the pattern's selvedge and the row's side) makes it what the selvedge is.
  bool edge = false;
  bool operator==(const Worked&) const = default;
};

struct Element;
using Sequence = std::vector<Element>;

struct Element {
  Worked stitch;          // when body is empty
  int count = 1;          // times the stitch, or the group, is worked
  Sequence body;          // a bracketed group
  bool is_group = false;
};

struct RowText;

// Where a part of a row with stitch markers ends: the row's end; a marker placed (pm),
// slipped (sm) or removed (rm) there; the next marker ("k to m"); or `before` stitches
// before it ("rep from * to 2 sts before m, k2"). See split_at_markers.
enum class MarkerEnd : std::uint8_t { row_end, place, slip, remove, to_marker, before_marker };

struct MarkedPart;

struct RowText {
  Sequence before;              // everything, when there is no *repeat
  std::optional<Sequence> star; // *...; rep from *, or "(p2, k2) to 3 sts before end"
  std::optional<int> to_last;   // "to last N sts"
  Sequence after;               // what follows "rep from * ..."
  // "knit the knit sts and purl the purl sts": every stitch worked as it shows.
  bool as_they_appear = false;
  // With as_they_appear: "p over k and k over p", each stitch worked as the other (moss).
  bool opposite = false;
  // "(WS) k2, p2": the side the row says it is worked from, printed before its stitches.
  std::optional<Side> side;
  // A row that places, slips or works to stitch markers: its parts in working order, each
  // worked across the stitches up to where it ends (the rest of this RowText is empty).
  std::vector<MarkedPart> parts;
};

struct MarkedPart {
  RowText text;
  MarkerEnd end = MarkerEnd::row_end;
  int before = 0;  // for before_marker: the stitches left before the marker
};

// Spellings of an edge stitch ("edge st", "selvedge st", "sel st", "sel s") and of
// markers placed or slipped ("pm", "sm", "place marker"), which work no stitch; any case.
bool is_edge_stitch(std::string_view spelled);
bool is_marker(std::string_view spelled);

// Parses a row's text. `yarn_ids` are the declared yarns a stitch may name after it
// ("k2 B"); their index is the Worked::yarn of such a stitch. Without `hints` an unknown
// stitch's message has no "did you mean" (for callers that only ask whether a line is a
// row: the hint costs a search of every spelling). A text over max_row_text_bytes is an
// error.
inline constexpr std::size_t max_row_text_bytes = 1u << 20;
std::variant<RowText, TextError> parse_row(std::string_view text, std::span<const std::string> yarn_ids, bool hints = true);

// A row's text cut at its stitch markers, when it has any, each part's words as the row
// parser reads them ("k to m" and "to 2 sts before m" as "to end": the work gives the
// part its room); nothing for a row without markers. Marker words inside brackets are
// not cut at.
struct MarkedText {
  std::string text;
  MarkerEnd end = MarkerEnd::row_end;
  int before = 0;
};
std::optional<std::vector<MarkedText>> split_at_markers(std::string_view text);
// What a marker's words do ("pm", "slip marker", "rm"), lower case; nothing for others.
std::optional<MarkerEnd> marker_word(std::string_view spelled);

// Works a parsed row across `live` stitches, in working order: a text without a repeat
// is repeated until the stitches are used; a *repeat fills what the fixed stitches leave.
// A text worked as its stitches appear is an error here: the caller knows how they show.
// `row` is the row's number, for messages.
std::variant<std::vector<Worked>, TextError> work_row(const RowText& text, std::string_view source, int live, int row);


// The stitches of a text without a *repeat, worked once (a part of a row up to a marker).
std::variant<std::vector<Worked>, TextError> work_once(const RowText& text, std::string_view source, int row);

// A row's text in quotes for messages, shortened past 60 characters.
std::string quote_row(std::string_view text);

// Live stitches worked by a sequence of stitches.
int consumed(std::span<const Worked> stitches);

// The stitches of one row worked on `side`, in working order, as face-view ops left to
// right: right-side rows are worked right to left, so their order reverses; wrong-side
// stitches show their face (k as p). `yarn` replaces Worked::yarn == -1.
std::variant<std::vector<Op>, TextError> face_view(std::span<const Worked> worked, Side side, int yarn);

}  // namespace knitc::language
