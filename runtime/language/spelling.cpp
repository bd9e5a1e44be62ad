#include "language/spelling.hpp"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <charconv>
#include <map>
#include <set>

#include "language/words.hpp"

namespace knitc::language {

namespace {

bool alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }
bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Typography a word processor or a web page puts into pattern text, as ASCII.
constexpr std::pair<std::string_view, std::string_view> typography[] = {
    {"\u2018", "'"}, {"\u2019", "'"}, {"\u201A", "'"}, {"\u201B", "'"}, {"\u2032", "'"},
    {"\u201C", "\""}, {"\u201D", "\""}, {"\u201E", "\""}, {"\u2033", "\""},
    {"\u2010", "-"}, {"\u2011", "-"}, {"\u2012", "-"}, {"\u2013", "-"}, {"\u2014", "-"}, {"\u2015", "-"}, {"\u2212", "-"},
    {"\u00D7", "x"}, {"\u2715", "x"},
    {"\u00A0", " "}, {"\u2002", " "}, {"\u2003", " "}, {"\u2009", " "}, {"\u202F", " "}, {"\u200B", ""}, {"\uFEFF", ""},
    {"\u2026", "..."}, {"\u2217", "*"}, {"\uFF0A", "*"}, {"\u204E", "*"},
};

// Modifiers and verbs written as prose, longest first within each meaning: the phrase as
// knitters write it, and the abbreviation words.cpp spells it with.
constexpr ProsePhrase prose[] = {
    {"with the yarn in front", "wyif"}, {"with the yarn at the front", "wyif"}, {"with yarn at the front", "wyif"},
    {"keeping the yarn in front", "wyif"}, {"keeping yarn in front", "wyif"}, {"keeping yarn at front", "wyif"},
    {"with yarn in front", "wyif"}, {"with yarn at front", "wyif"}, {"with yarn forward", "wyif"},
    {"with yarn to front", "wyif"}, {"holding working yarn in front", "wyif"}, {"holding the yarn in front", "wyif"},
    {"holding yarn in front", "wyif"}, {"with working yarn in front", "wyif"}, {"yarn in front", "wyif"}, {"wyf", "wyif"},
    {"with the yarn in back", "wyib"}, {"with the yarn at the back", "wyib"}, {"with yarn at the back", "wyib"},
    {"keeping the yarn at the back", "wyib"}, {"keeping the yarn in back", "wyib"}, {"keeping yarn at back", "wyib"},
    {"keeping yarn in back", "wyib"}, {"keeping yarn behind", "wyib"}, {"with yarn in back", "wyib"},
    {"with yarn at back", "wyib"}, {"with yarn behind", "wyib"}, {"with yarn to back", "wyib"},
    {"holding working yarn in back", "wyib"}, {"holding the yarn in back", "wyib"}, {"holding yarn in back", "wyib"},
    {"with working yarn in back", "wyib"}, {"yarn in back", "wyib"}, {"yarn at back", "wyib"}, {"wyb", "wyib"},
    {"as if to knit", "kwise"}, {"knitwise", "kwise"}, {"knit-wise", "kwise"}, {"knit wise", "kwise"},
    {"k-wise", "kwise"}, {"kw", "kwise"},
    {"as if to purl", "pwise"}, {"purlwise", "pwise"}, {"purl-wise", "pwise"}, {"purl wise", "pwise"},
    {"p-wise", "pwise"}, {"pw", "pwise"},
    {"through the back of the loops", "tbl"}, {"through the back of the loop", "tbl"}, {"through the back loops", "tbl"},
    {"through the back loop", "tbl"}, {"through back of the loop", "tbl"}, {"through back of loop", "tbl"},
    {"through back loops", "tbl"}, {"through back loop", "tbl"}, {"through the back", "tbl"},
    {"in back loop", "tbl"}, {"in the back loop", "tbl"},
    {"together", "tog"},
    {"pass the slipped stitch over", "psso"}, {"pass the slipped st over", "psso"}, {"pass slipped stitch over", "psso"},
    {"pass slipped st over", "psso"}, {"pass the slip stitch over", "psso"}, {"pass slip stitch over", "psso"},
    {"pass sl st over", "psso"},
    {"pass the 2 slipped stitches over", "p2sso"}, {"pass 2 slipped stitches over", "p2sso"},
    {"pass the 2 slipped sts over", "p2sso"}, {"pass 2 slipped sts over", "p2sso"}, {"pass 2 sl sts over", "p2sso"},
    {"yarn over needle", "yo"}, {"yarn round needle", "yo"}, {"wool round needle", "yo"}, {"wool over needle", "yo"},
    {"yarn forward", "yo"}, {"yarn fwd", "yo"}, {"wool forward", "yo"}, {"wool fwd", "yo"}, {"yarn over", "yo"},
    {"wool over", "yo"}, {"wfwd", "yo"}, {"wfd", "yo"}, {"wrn", "yo"}, {"wf", "yo"},
    // "inc in next st": an increase that says not which (refused as "inc").
    {"inc 1 in next st", "inc"}, {"inc in next stitch", "inc"}, {"inc in next st", "inc"}, {"inc in next", "inc"},
    // "rep from *, ending k1": what closes the row follows, as after a comma.
    {"ending with", ","}, {"ending in", ","}, {"ending", ","}, {"end with", ","},
    // How far: "p across row", "k until last 5 sts", "knit all stitches", "rep from * cont to end".
    {"across the row", "to end"}, {"across row", "to end"}, {"across the round", "to end"}, {"across round", "to end"},
    {"across rnd", "to end"}, {"across to", "to"}, {"across", "to end"}, {"until", "to"}, {"all stitches", "to end"},
    {"all sts", "to end"}, {"continuing", ""}, {"cont", ""},
    // Vintage rows in words.
    {"plain knitting", "k to end"}, {"knit plain", "k to end"}, {"pearl knitting", "p to end"},
    {"purl knitting", "p to end"}, {"pearl", "purl"}, {"all the way to end", "to end"},
    // Counts in words: "knit two together", "to last three sts".
    {"one", "1"}, {"two", "2"}, {"three", "3"}, {"four", "4"}, {"five", "5"}, {"six", "6"}, {"seven", "7"},
    {"eight", "8"}, {"nine", "9"}, {"ten", "10"}, {"eleven", "11"}, {"twelve", "12"}, {"eighteen", "18"},
    // The *repeat closed in words: "repeat between *'s", "repeat *-* to end".
    {"repeat between *'s", "rep from *"}, {"rep between *'s", "rep from *"}, {"repeat between *s", "rep from *"},
    {"rep between *s", "rep from *"}, {"repeat from *-*", "rep from *"}, {"rep from *-*", "rep from *"},
    {"repeat *-*", "rep from *"}, {"rep *-*", "rep from *"},
    // "k all": the rest of the row.
    {"all", "to end"},
};

// `phrase` (lower case) at `at` of `low` (the text lower-cased), as whole words.
bool phrase_at(std::string_view low, std::size_t at, std::string_view phrase) {
  if (low.compare(at, phrase.size(), phrase) != 0) return false;
  if (at > 0 && alnum(low[at - 1])) return false;
  const std::size_t end = at + phrase.size();
  return end == low.size() || !alnum(low[end]);
}

std::string replace_phrases(std::string s) {
  // One lower-case copy, made again only after a phrase was replaced: a long row must not
  // cost a copy per phrase.
  std::string low = lower(s);
  for (const auto& [phrase, with] : prose) {
    if (low.find(phrase) == std::string::npos) continue;
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
      if (phrase_at(low, i, phrase)) {
        out += with;
        i += phrase.size();
      } else {
        out += s[i++];
      }
    }
    s = std::move(out);
    low = lower(s);
  }
  return s;
}

// A word that continues what a dot abbreviated: "sl. 1", "rep. from", "k 2 tog. tbl".
bool continues(std::string_view next_word) {
  if (next_word.empty()) return false;
  if (std::isdigit(static_cast<unsigned char>(next_word[0]))) return true;
  const std::string w = lower(next_word);
  for (std::string_view c : {"from", "to", "tog", "tbl", "wyif", "wyib", "pwise", "kwise", "psso", "st", "sts", "times"})
    if (w == c) return true;
  return false;
}

// Dots inside an abbreviation ("p.s.s.o"), after one ("rep.", "sl."), and between two
// instructions ("k2. P2": a comma).
std::string without_dots(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c != '.' || i == 0 || !alnum(s[i - 1])) {
      out += c;
      continue;
    }
    while (i + 1 < s.size() && s[i + 1] == '.') ++i;  // "k2.." and "k2..." as one dot
    if (i + 1 < s.size() && alnum(s[i + 1])) continue;  // inside: "p.s.s.o"
    std::size_t j = i + 1;
    while (j < s.size() && space(s[j])) ++j;
    if (j == s.size() || j == i + 1) continue;  // the text's end, or ")" / "," / ";" right after
    std::size_t k = j;
    while (k < s.size() && (alnum(s[k]) || s[k] == '.')) ++k;
    if (!continues(s.substr(j, k - j))) out += ',';
  }
  return out;
}

}  // namespace

std::string typography_as_ascii(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    if (static_cast<unsigned char>(s[i]) < 0x80) {
      out += s[i++];
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : typography) {
      if (s.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += s[i++];
  }
  return out;
}

namespace {

// Words that mean the same in any spelling of a stitch: "knit 2 tog" is "k2tog", "slip 1
// stitch" is "sl1".
std::string_view canonical_word(std::string_view w) {
  const std::string l = lower(w);
  if (l == "knit") return "k";
  if (l == "purl") return "p";
  if (l == "slip" || l == "slipped") return "sl";
  if (l == "st" || l == "sts" || l == "stitch" || l == "stitches" || l == "the" || l == "next") return "";
  return w;
}

// The letters and digits of a spelling, lower case, in its canonical words.
std::string squeeze(std::string_view spelling) {
  std::string out;
  std::size_t i = 0;
  while (i < spelling.size()) {
    while (i < spelling.size() && space(spelling[i])) ++i;
    const std::size_t start = i;
    while (i < spelling.size() && !space(spelling[i])) ++i;
    for (char c : canonical_word(spelling.substr(start, i - start)))
      if (alnum(c) || static_cast<unsigned char>(c) >= 0x80) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

constexpr AmbiguousSpelling ambiguous_table[] = {
    {"inc", "kfb|m1|yo", "an increase, but the pattern does not say which"},
    {"dec", "k2tog|ssk|p2tog", "a decrease, but the pattern does not say which"},
    {"make 1", "m1|yo", "a lifted increase in modern patterns, a yarn over (\"make one by bringing the wool forward\") in Victorian and early 20th-century ones"},
    {"kb", "k tbl|k below", "knit into the back of the stitch in British patterns, knit into the stitch below in Walker's and in brioche"},
    {"k1b", "k tbl|k below", "knit into the back of the stitch in British patterns, knit into the stitch below in Walker's and in brioche"},
    {"pb", "p tbl|p below", "purl into the back of the stitch in British patterns, purl into the stitch below in Walker's and in brioche"},
    {"p1b", "p tbl|p below", "purl into the back of the stitch in British patterns, purl into the stitch below in Walker's and in brioche"},
    {"c2", "C2F|C2B", "a cross, but not which way"},
    {"c4", "C4F|C4B", "a cable, but not which way it crosses"},
    {"c6", "C6F|C6B", "a cable, but not which way it crosses"},
    {"c8", "C8F|C8B", "a cable, but not which way it crosses"},
};

std::vector<std::string> split_bars(std::string_view s) {
  std::vector<std::string> out;
  while (!s.empty()) {
    const auto bar = s.find('|');
    out.emplace_back(s.substr(0, bar));
    s = bar == std::string_view::npos ? std::string_view{} : s.substr(bar + 1);
  }
  return out;
}

// Every spelling's squeezed key, as written and as normalised ("sl pw" and "sl pwise"),
// with the stitches it spells; a key two stitches share is ambiguous.
const std::map<std::string, std::set<StitchId>>& keys() {
  static const auto all = [] {
    std::map<std::string, std::set<StitchId>> m;
    for (std::size_t i = 0; i < stitch_table().size(); ++i) {
      const auto id = static_cast<StitchId>(i);
      for_each_spelling(id, [&](std::string_view w) {
        m[squeeze(w)].insert(id);
        m[squeeze(normalise(w))].insert(id);
      });
    }
    return m;
  }();
  return all;
}

const AmbiguousSpelling* refused(const std::string& key) {
  for (const AmbiguousSpelling& a : ambiguous_table)
    if (squeeze(a.written) == key) return &a;
  return nullptr;
}

std::string join(std::span<const std::string_view> words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + std::string(w);
  return out;
}

}  // namespace

namespace {

// "repeat [k5, sl5 wyib] across": the bracket says what repeats; the word goes.
std::string without_repeat_before_bracket(std::string s) {
  const std::string low = lower(s);
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool dropped = false;
    for (std::string_view word : {"repeat", "rep"}) {
      if (!phrase_at(low, i, word)) continue;
      std::size_t j = i + word.size();
      while (j < s.size() && space(s[j])) ++j;
      if (j < s.size() && (s[j] == '[' || s[j] == '(')) {
        i = j;
        dropped = true;
      }
      break;
    }
    if (!dropped) out += s[i++];
  }
  return out;
}

// "to last 6: P4": a colon inside a row's text parts two instructions, as a comma does.
std::string without_colons(std::string s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == ':' && (i + 1 == s.size() || space(s[i + 1]))) s[i] = ',';
    // "to last 5:P3"
    if (s[i] == ':' && i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1])) && i + 1 < s.size() &&
        std::isalpha(static_cast<unsigned char>(s[i + 1])))
      s[i] = ',';
    // "k1, p1 - all the way across": a dash between words parts nothing.
    if (s[i] == '-' && i > 0 && space(s[i - 1]) && i + 1 < s.size() && space(s[i + 1])) s[i] = ' ';
  }
  return s;
}

}  // namespace

namespace {
std::string normalise_once(std::string_view text) {
  return without_repeat_before_bracket(replace_phrases(without_colons(without_dots(typography_as_ascii(text)))));
}
}  // namespace

std::string normalise(std::string_view text) {
  // One pass can make what another step reads ("rep *-*rep(k1": the second "rep" goes
  // before its bracket, and "rep *-*" is then a phrase): passes until nothing changes, so
  // that normalise(normalise(t)) == normalise(t). A second pass is the most any text
  // has needed; the cap only guards against a cycle no rule is known to make.
  std::string s = normalise_once(text);
  for (int pass = 0; pass < 16; ++pass) {
    std::string next = normalise_once(s);
    if (next == s) break;
    s = std::move(next);
  }
  return s;
}

std::span<const AmbiguousSpelling> ambiguous_spellings() { return ambiguous_table; }

std::span<const ProsePhrase> prose_phrases() { return prose; }

std::string ambiguous_message(const Ambiguous& a) {
  std::string names;
  for (std::size_t i = 0; i < a.candidates.size(); ++i)
    names += (i == 0 ? "" : i + 1 == a.candidates.size() ? " or " : ", ") + a.candidates[i];
  return "'" + a.written + "' could mean " + names + " (" + a.why + "); write the one the pattern means";
}

std::variant<std::monostate, Reading, Ambiguous> read_stitch(std::string_view written) {
  const std::string_view one[] = {written};
  return read_stitch(std::span<const std::string_view>(one));
}

std::variant<std::monostate, Reading, Ambiguous> read_stitch(std::span<const std::string_view> words) {
  const std::string written = join(words);
  if (const auto id = find_stitch(written)) return Reading{*id};
  const std::string key = squeeze(written);
  if (key.empty()) return std::monostate{};
  auto ambiguous = [&](const AmbiguousSpelling* a, const std::set<StitchId>* ids) {
    Ambiguous out{written, a ? std::string(a->why) : "two stitches are written so", {}};
    if (a) out.candidates = split_bars(a->candidates);
    else
      for (StitchId id : *ids) out.candidates.emplace_back(stitch(id).name);
    return out;
  };
  if (const auto* a = refused(key)) return ambiguous(a, nullptr);
  const auto& all = keys();
  auto look = [&](const std::string& k) -> const std::set<StitchId>* {
    const auto it = all.find(k);
    return it == all.end() ? nullptr : &it->second;
  };
  if (const auto* ids = look(key)) {
    if (ids->size() > 1) return ambiguous(nullptr, ids);
    return Reading{*ids->begin()};
  }
  // A count run in after the letters that begin it: "p5", "sl1pw", "k2tbl", "sl5wyif".
  std::size_t letters = 0;
  while (letters < key.size() && std::isalpha(static_cast<unsigned char>(key[letters]))) ++letters;
  std::size_t digits = letters;
  while (digits < key.size() && std::isdigit(static_cast<unsigned char>(key[digits]))) ++digits;
  if (letters == 0 || digits == letters) return std::monostate{};
  const std::string base = key.substr(0, letters) + key.substr(digits);
  if (const auto* a = refused(base)) return ambiguous(a, nullptr);
  const auto* ids = look(base);
  if (!ids) return std::monostate{};
  if (ids->size() > 1) return ambiguous(nullptr, ids);
  Reading r{*ids->begin()};
  r.count_written = true;
  const std::string_view number = std::string_view(key).substr(letters, digits - letters);
  int n = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), n);
  if (ec != std::errc() || number.size() > 6 || n > 100'000 || n < 1) r.count_too_large = true;
  r.count = r.count_too_large ? 1 : n;
  return r;
}

}  // namespace knitc::language
