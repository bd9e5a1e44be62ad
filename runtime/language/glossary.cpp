#include "language/glossary.hpp"

#include <algorithm>
#include <cctype>
#include <regex>
#include <variant>
#include <vector>

#include "language/spelling.hpp"
#include "language/written.hpp"

namespace knitc::language {

namespace {

constexpr std::size_t longest_cross_words = 300;  // bytes of a cross described in brackets

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

int number_word(const std::string& w) {
  if (w.empty()) return 1;
  if (w == "one") return 1;
  if (w == "two") return 2;
  if (w == "three") return 3;
  if (w == "four") return 4;
  if (w.size() <= 2 && std::all_of(w.begin(), w.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
    return std::stoi(w);
  return 0;
}

// Where `word` (lower case) stands in `low` as a whole word, from `from`.
std::size_t find_word(const std::string& low, const std::string& word, std::size_t from = 0) {
  for (std::size_t at = low.find(word, from); at != std::string::npos; at = low.find(word, at + 1)) {
    const bool starts = at == 0 || !word_char(low[at - 1]);
    const bool ends = at + word.size() == low.size() || !word_char(low[at + word.size()]);
    if (starts && ends) return at;
  }
  return std::string::npos;
}

}  // namespace

namespace {

// A cross worked in words: "slip 2 sts to cn, hold in back, k2, p2 from cn", in the words
// of words_of() below (k and p for knit and purl). Groups: 1 held, 2 front|back, 3 k|p
// first, 4 its count, 5 k|p from the needle, 6 its count.
const std::regex& cross_regex() {
  static const std::string count = R"((\d{1,2})?)";
  static const std::string st = R"((?:\s*(?:sts?|stitches))?)";
  static const std::string cn = R"((?:the\s+|a\s+)?(?:cn|cable needle|cbn|dpn|third needle|stitch holder|holder))";
  static const std::regex cross(
      R"((?:to make a cable\s*,?\s*)?(?:cable \d+\s*sts?\s*,?\s*)?(?:sl|slip)(?:\s+off)?\s+(?:the\s+)?(?:next\s+|first\s+)?(\d{1,2}))" + st +
          R"(\s+(?:to|onto|on to|on)\s+)" + cn + R"(\s*[,;]?\s*(?:and\s+)?(?:hold|leave|held|place|keep|keeping)\s+(?:it\s+|them\s+|)" + cn +
          R"(\s+)?(?:to|in|at)\s+(?:the\s+)?(front|back))"
          R"((?:\s+of\s+(?:the\s+)?work)?\s*[,;]?\s*(?:then\s+)?(k|p)\s*(?:the\s+)?(?:next\s+)?)" + count + st +
          R"((?:\s+from\s+(?:the\s+)?(?:left|lh|ln|left-hand)(?:\s+needle)?)?\s*[,;]?\s*(?:then\s+)?(k|p)\s*(?:the\s+)?)" + count + st +
          R"(\s+(?:from|off|on)\s+)" + cn,
      std::regex::icase);
  return cross;
}

// The text as cross_regex() reads it: normalised, "knit" and "purl" as k and p.
std::string words_of(std::string_view text) {
  static const std::regex knit(R"(\bknit\b)", std::regex::icase), purl(R"(\bpurl\b)", std::regex::icase);
  return std::regex_replace(std::regex_replace(normalise(text), knit, "k"), purl, "p");
}

// The stitch table's name of the cross a match of cross_regex() describes.
std::optional<std::string> cross_named(const std::smatch& m) {
  const int held = number_word(m[1]);
  const bool front = lower(m[2].str()) == "front";
  const bool first_purl = lower(m[3].str()) == "p";
  const int first = m[4].matched ? number_word(m[4]) : held;
  const bool held_purl = lower(m[5].str()) == "p";
  const int from_cn = m[6].matched ? number_word(m[6]) : held;
  if (held == 0 || first == 0 || from_cn != held) return std::nullopt;
  std::string name;
  // A right cross holds its stitches behind, and those worked first lie on top; a left
  // cross holds them in front, on top. Purls only under the knit ones (a purl cross).
  if (!front && !first_purl) name = std::to_string(first) + "/" + std::to_string(held) + (held_purl ? " RPC" : " RC");
  else if (front && !held_purl) name = std::to_string(held) + "/" + std::to_string(first) + (first_purl ? " LPC" : " LC");
  else return std::nullopt;
  const auto id = find_stitch(name);
  if (!id) return std::nullopt;
  return std::string(stitch(*id).name);
}

// A bobble worked in words: "[k1, p1, k1, p1], turn; K4, turn; P4, pass 2nd st over 1st
// ...", "(k1, yo, k1, yo, k1) in next st, turn, p5, turn, k5, turn, p5, turn, k5tog": the
// loops the first bracket makes in one stitch, and a row more for each turn followed by a
// row of that many (k5tog, the gather, is not one). Its name in the stitch table.
std::optional<std::string> bobble_in_words(std::string_view definition) {
  const std::string low = lower(words_of(definition.substr(0, longest_definition)));
  const std::size_t open = low.find_first_of("[(");
  const std::size_t close = open == std::string::npos ? open : low.find_first_of("])", open);
  if (close == std::string::npos || find_word(low, "turn", close) == std::string::npos) return std::nullopt;
  static const std::regex item(R"(\b(k|p|yo)\s*(\d?)\b)");
  int loops = 0;
  const std::string group = low.substr(open + 1, close - open - 1);
  for (auto m = std::sregex_iterator(group.begin(), group.end(), item); m != std::sregex_iterator(); ++m)
    loops += (*m)[2].length() > 0 ? std::stoi((*m)[2]) : 1;
  if (loops < bobble_loops_min || loops > bobble_loops_max) return std::nullopt;
  const std::regex row(R"(\b(k|p)\s*)" + std::to_string(loops) + R"(\b)");
  int rows = 1;
  for (std::size_t at = find_word(low, "turn", close); at != std::string::npos;) {
    const std::size_t next = find_word(low, "turn", at + 4);
    const std::string part = low.substr(at + 4, next == std::string::npos ? std::string::npos : next - at - 4);
    if (std::regex_search(part, row)) ++rows;
    at = next;
  }
  if (rows > bobble_rows_max) return std::nullopt;
  return bobble_name(loops, rows);
}

bool only_punctuation(std::string_view s) { return s.find_first_not_of(" \t.,;:") == std::string_view::npos; }

}  // namespace

std::optional<std::string> cross_in_words(std::string_view definition) {
  if (definition.size() > longest_definition) return std::nullopt;
  const std::string words = words_of(definition);
  std::smatch m;
  if (!std::regex_search(words, m, cross_regex()) || !only_punctuation(m.suffix().str())) return std::nullopt;
  return cross_named(m);
}

namespace {

// `nested`: the definition after a heading ("Notes: B2 = ..."), read once, no deeper.
std::optional<GlossaryEntry> read_line(std::string_view line, int number, bool nested);

}  // namespace

std::optional<GlossaryEntry> read_glossary_line(std::string_view line, int number) { return read_line(line, number, false); }

namespace {

std::optional<GlossaryEntry> read_line(std::string_view line, int number, bool nested) {
  const std::string_view t = trim(line.substr(0, longest_definition + longest_abbreviation + 8));
  std::size_t sep = std::string_view::npos, width = 0;
  for (std::string_view mark : {":", "=", " - ", "- "}) {
    const std::size_t at = t.find(mark);
    if (at != std::string_view::npos && at < sep) sep = at, width = mark.size();
  }
  if (sep == std::string_view::npos) return std::nullopt;
  const std::string_view abbreviation = trim(t.substr(0, sep));
  const std::string_view definition = trim(t.substr(sep + width));
  if (abbreviation.empty() || definition.empty() || abbreviation.size() > longest_abbreviation) return std::nullopt;
  if (!word_char(abbreviation.front())) return std::nullopt;
  if (std::count(abbreviation.begin(), abbreviation.end(), ' ') > 2) return std::nullopt;
  for (char c : abbreviation)
    if (!word_char(c) && c != ' ' && c != '/' && c != '&' && c != '-') return std::nullopt;
  GlossaryEntry e{std::string(abbreviation), number, std::string(definition.substr(0, longest_definition)), std::nullopt};
  // A bobble's working says its size, which MB alone does not: the working wins.
  if (auto bobble = bobble_in_words(e.definition)) {
    e.means = std::move(bobble);
    return e;
  }
  // An abbreviation knitc reads already is the glossary explaining it: nothing to learn.
  if (is_edge_stitch(abbreviation) || is_marker(abbreviation) ||
      std::holds_alternative<Reading>(read_stitch(normalise(abbreviation)))) {
    e.known = true;
    return e;
  }
  // "Notes: B2 = Knit 2 stitches on each end": a heading before the definition; and
  // "Stitch Explanation: 4-st RC, Slip 2 sts to cn ...", the abbreviation before a comma.
  if (!nested && definition.find_first_of(":=") != std::string_view::npos) {
    if (auto inner = read_line(definition, number, true); inner && !inner->known) return inner;
  } else if (const auto comma = definition.find(", "); !nested && comma != std::string_view::npos && comma <= longest_abbreviation) {
    const std::string as_defined = std::string(definition.substr(0, comma)) + ": " + std::string(definition.substr(comma + 2));
    if (auto inner = read_line(as_defined, number, true); inner && !inner->known && inner->means) return inner;
  }
  const auto reading = read_stitch(normalise(e.definition));
  if (const auto* r = std::get_if<Reading>(&reading); r && r->count == 1) e.means = std::string(stitch(r->stitch).name);
  else e.means = cross_in_words(e.definition);
  if (!e.means) {
    // "Knit 2 stitches on each end for border": the stitches before the words that say where.
    static const std::regex where(R"(\s+(?:on|at|for|in|of)\s+(?:each|both|the|every|a)\b.*$)", std::regex::icase);
    const std::string stitches = std::regex_replace(e.definition.substr(0, 200), where, "");
    if (stitches.size() < e.definition.size() && parse_row(stitches, {}, false).index() == 0) e.means = normalise(stitches);
  }
  return e;
}

}  // namespace

std::string with_glossary(std::string_view text, std::span<const GlossaryEntry> glossary) {
  std::vector<const GlossaryEntry*> read;
  for (const GlossaryEntry& e : glossary)
    if (e.means) read.push_back(&e);
  std::stable_sort(read.begin(), read.end(),
                   [](const GlossaryEntry* a, const GlossaryEntry* b) { return a->abbreviation.size() > b->abbreviation.size(); });
  std::string out(text);
  for (const GlossaryEntry* e : read) {
    const std::string word = lower(e->abbreviation);
    const std::string low = lower(out);
    std::string next;
    std::size_t from = 0;
    for (std::size_t at = find_word(low, word); at != std::string::npos; at = find_word(low, word, at + word.size())) {
      next.append(out, from, at - from);
      next += *e->means;
      from = at + word.size();
    }
    next.append(out, from, std::string::npos);
    out = std::move(next);
  }
  return out;
}

std::string with_crosses_in_words(std::string_view text) {
  std::string out(text);
  for (std::size_t open = out.find('('); open != std::string::npos; open = out.find('(', open + 1)) {
    // A cross in words is a sentence, not a page: look no further than its length.
    const std::size_t window = std::min(out.size(), open + longest_cross_words);
    const std::size_t found = std::string_view(out).substr(open, window - open).find(')');
    if (found == std::string_view::npos) continue;
    const std::size_t close = open + found;
    const auto name = cross_in_words(std::string_view(out).substr(open + 1, close - open - 1));
    if (!name) continue;
    std::size_t from = out.find_last_of(",;*", open);
    from = from == std::string::npos ? 0 : from + 1;
    while (from < open && out[from] == ' ') ++from;
    out.replace(from, close + 1 - from, *name);
    open = from;
  }
  // "*p3, slip 2 sts to CN and hold in front; k2 from LN, then k2 from CN; rep from *":
  // a cross in words where it is worked, in a row short enough to read so.
  if (out.size() > longest_definition) return out;
  const std::string low = lower(out);
  if (low.find("cn") == std::string::npos && low.find("cable needle") == std::string::npos &&
      low.find("holder") == std::string::npos)
    return out;
  std::string words = words_of(out);
  std::string rewritten;
  std::smatch m;
  bool any = false;
  while (std::regex_search(words, m, cross_regex())) {
    const auto name = cross_named(m);
    rewritten += m.prefix().str() + (name ? *name : m.str());
    any = any || name.has_value();
    words = m.suffix().str();
  }
  return any ? rewritten + words : out;
}

const GlossaryEntry* unread_abbreviation_in(std::string_view text, std::span<const GlossaryEntry> glossary) {
  const std::string low = lower(text);
  for (const GlossaryEntry& e : glossary)
    if (!e.means && find_word(low, lower(e.abbreviation)) != std::string::npos) return &e;
  return nullptr;
}

}  // namespace knitc::language
