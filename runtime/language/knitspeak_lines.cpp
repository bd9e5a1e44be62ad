// Printed text line by line: the lines of a block made plain and cut into rows, and each
// row's label ("Row 1 (RS):", "1st row.-", "Rows 2 and 4"), a repeat of rows ("Repeat rows
// 1-4"), and a stated count ("(14 sts)"). Internal to knitspeak.cpp.
#include "language/knitspeak_lines.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <regex>

#include "language/spelling.hpp"
#include "language/written.hpp"

namespace knitc::language::knitspeak_lines {


constexpr int max_row_number = 100'000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Bullets and list marks before a line; never "*", which starts a repeat.
std::string_view without_bullet(std::string_view s) {
  for (std::string_view mark : {"\u2022", "\u00b7", "\u2013", "- ", "+ "}) {
    if (s.substr(0, mark.size()) == mark) return trim(s.substr(mark.size()));
  }
  return s;
}

// The words of a number list, "1, 5, and 9", "1-3 and 8-10", "from 1 to 2": every number,
// or nothing if the text is anything else. A list that is one but cannot be honoured (a
// row past max_row_number, "2-" with no end, "9-3") also gives nothing, and `problem`
// says why: that is an error, not a line to skip.
std::optional<std::vector<int>> numbers(std::string_view text, std::string& problem) {
  std::string t = lower(text);
  for (std::string_view dash : {"\u2013", "\u2014"}) {  // en and em dashes as ranges
    for (std::size_t at; (at = t.find(dash)) != std::string::npos;) t.replace(at, dash.size(), "-");
  }
  std::vector<std::string> words;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) words.push_back(word);
    word.clear();
  };
  for (char c : t) {
    if (std::isdigit(static_cast<unsigned char>(c)) || std::isalpha(static_cast<unsigned char>(c))) {
      word += c;
    } else {
      flush();
      if (c == '-') words.push_back("-");
    }
  }
  flush();
  std::vector<int> out;
  const std::string last = std::to_string(max_row_number);
  auto digits = [](const std::string& w) {
    return !w.empty() && std::all_of(w.begin(), w.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  };
  auto number = [&](const std::string& w) -> std::optional<int> {
    if (!digits(w)) return std::nullopt;
    int v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || v > max_row_number) {
      problem = "row " + (w.size() > 12 ? w.substr(0, 12) + "..." : w) + " is past row " + last +
                ", the last a knitspeak text may number";
      return std::nullopt;
    }
    if (v < 1) {
      problem = "rows are numbered from 1, not " + w;
      return std::nullopt;
    }
    return v;
  };
  auto is_range_word = [](const std::string& w) { return w == "-" || w == "to" || w == "through"; };
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == "and" || words[i] == "from") continue;
    const auto a = number(words[i]);
    if (!a) return std::nullopt;
    if (i + 1 < words.size() && is_range_word(words[i + 1])) {
      if (i + 2 >= words.size() || !digits(words[i + 2])) {
        problem = "the range " + words[i] + "-" + " has no last row";
        return std::nullopt;
      }
      const auto b = number(words[i + 2]);
      if (!b) return std::nullopt;
      if (*b < *a) {
        problem = "the range " + words[i] + "-" + words[i + 2] + " runs backwards";
        return std::nullopt;
      }
      if (out.size() + static_cast<std::size_t>(*b - *a) >= static_cast<std::size_t>(max_row_number)) {
        problem = "the rows listed come to more than " + last;
        return std::nullopt;
      }
      for (int n = *a; n <= *b; ++n) out.push_back(n);
      i += 2;
      continue;
    }
    if (out.size() >= static_cast<std::size_t>(max_row_number)) {
      problem = "the rows listed come to more than " + last;
      return std::nullopt;
    }
    out.push_back(*a);
  }
  if (out.empty()) return std::nullopt;
  return out;
}


// The side marks a label may carry, as printed.
constexpr std::pair<std::string_view, Side> side_marks[] = {
    {"(rs)", Side::right}, {"(ws)", Side::wrong}, {"[rs]", Side::right}, {"[ws]", Side::wrong},
    {"(right side)", Side::right}, {"(wrong side)", Side::wrong}, {"(right side row)", Side::right},
    {"(wrong side row)", Side::wrong}, {"(right side rows)", Side::right}, {"(wrong side rows)", Side::wrong},
    {"(rs rows)", Side::right}, {"(ws rows)", Side::wrong}, {"(rs row)", Side::right}, {"(ws row)", Side::wrong},
    {"(right side rows)", Side::right},
};

// A label's head (lower case, its noun taken off) as row numbers and a side, or nothing.
std::optional<Label> head_rows(std::string head, std::string& problem) {
  Label out;
  head.erase(std::unique(head.begin(), head.end(), [](char a, char b) { return a == ' ' && b == ' '; }), head.end());
  for (std::string_view word : {" inclusive", " incl.", " incl"}) {
    const auto m = head.rfind(word);
    if (m != std::string::npos && m + word.size() == head.size()) head.erase(m);
  }
  for (std::string_view every : {"(and every ws row)", "(and all ws rows)", "(and every rs row)", "(and all rs rows)",
                                 "and all other ws rows", "and all other rs rows", "and every other ws row",
                                 "and every ws row", "and all ws rows", "and all following ws rows", "and alt rows",
                                 "and alt. rows", "and alternate rows", "and all alternate rows", "and every alternate row",
                                 "and all even rows", "and every other row", "and all foll alt rows", "and all alt.", "and all alternate",
                                 "and every alternate", "and alt.", "and alt", "and alternate"}) {
    const auto m = head.find(every);
    if (m != std::string::npos) {
      out.every_other = true;
      head.erase(m, every.size());
    }
  }
  for (const auto& [mark, side] : side_marks) {
    const auto m = head.find(mark);
    if (m != std::string::npos) {
      out.side = side;
      head.erase(m, mark.size());
    }
  }
  const auto rows = numbers(head, problem);
  if (!rows) return std::nullopt;
  out.rows = *rows;
  if (out.every_other && out.rows.size() != 1) return std::nullopt;
  return out;
}

// "Row 2: k2, *k1, p8* k3 - and every following wrong side row": the every-other mark
// printed after the row's text.
void every_other_in_body(Label& l) {
  static const std::regex mark(
      R"([\s,;.-]*(?:and|&)\s+(?:every|all)\s+(?:following\s+|other\s+)?(?:ws|wrong side|wrong-side|alternate|alt\.?)\s+rows?[\s.]*$)");
  std::smatch m;
  const std::size_t tail = l.body.size() > 200 ? l.body.size() - 200 : 0;
  const std::string low = lower(std::string_view(l.body).substr(tail));
  if (l.rows.size() != 1 || !std::regex_search(low, m, mark)) return;
  l.body.resize(tail + static_cast<std::size_t>(m.position(0)));
  l.every_other = true;
}

// A side printed at the start of a row's text, "Row 1: (WS) slip 1, ...": taken off.
void side_in_body(Label& l) {
  every_other_in_body(l);
  const std::string low = lower(l.body);
  for (const auto& [mark, side] : side_marks) {
    if (low.rfind(mark, 0) == 0) {
      l.side = side;
      l.body = std::string(trim(std::string_view(l.body).substr(mark.size())));
      return;
    }
  }
}

// "1st", "2nd", "23rd", "4th" as 1, 2, 23, 4: vintage leaflets number rows so.
std::string without_ordinals(std::string_view l) {
  std::string out;
  for (std::size_t i = 0; i < l.size(); ++i) {
    out += l[i];
    if (!std::isdigit(static_cast<unsigned char>(l[i])) || i + 2 >= l.size()) continue;
    const std::string_view suffix = l.substr(i + 1, 2);
    const bool word_ends = i + 3 >= l.size() || !std::isalnum(static_cast<unsigned char>(l[i + 3]));
    if (word_ends && (suffix == "st" || suffix == "nd" || suffix == "rd" || suffix == "th")) i += 2;
  }
  return out;
}

// Where a label's head ends and the row begins: a colon, else a full stop or a dash
// after the numbers ("1st row.-K 2", "Row 1. K2", "Row 3 - k2"), else nothing.
std::vector<std::size_t> separators(std::string_view l, std::size_t from) {
  std::vector<std::size_t> out;
  if (const auto colon = l.find(':', from); colon != std::string_view::npos) out.push_back(colon);
  for (std::size_t i = from; i < l.size(); ++i) {
    const bool stop = l[i] == '.' && (i + 1 == l.size() || !std::isdigit(static_cast<unsigned char>(l[i + 1])));
    const bool dash = l[i] == '-' && i > 0 && l[i - 1] == ' ' && i + 1 < l.size() && l[i + 1] == ' ';
    if (stop || dash) out.push_back(i);
  }
  return out;
}

// After the separator: the rest of a ".-", ":-" or " - " and the spaces.
std::size_t body_start(std::string_view l, std::size_t sep) {
  std::size_t i = sep + 1;
  while (i < l.size() && (l[i] == '-' || l[i] == '.' || l[i] == ':' || std::isspace(static_cast<unsigned char>(l[i])))) ++i;
  return i;
}

bool noun_at(std::string_view l, std::size_t at, std::size_t& after) {
  // "R1:", "R 2:": a row, where a number follows.
  if (l.compare(at, 1, "r") == 0) {
    std::size_t d = at + 1;
    while (d < l.size() && l[d] == ' ') ++d;
    if (d < l.size() && d - at <= 2 && std::isdigit(static_cast<unsigned char>(l[d]))) {
      after = at + 1;
      return true;
    }
  }
  for (std::string_view noun : {"rounds", "round", "rnds", "rnd", "rows", "row"}) {
    if (l.compare(at, noun.size(), noun) == 0 &&
        (at + noun.size() == l.size() || !std::isalpha(static_cast<unsigned char>(l[at + noun.size()])))) {
      after = at + noun.size();
      return true;
    }
  }
  return false;
}

// "rows 1-4", "rnds 3 and 4", "from 1 to 2" after "repeat", and the vintage "as 1st and
// 2nd rows", "work as row 1": the rows, if that is what it says.
std::optional<std::vector<int>> repeated_rows(std::string_view body, std::string& problem) {
  std::string t = lower(trim(body));
  while (!t.empty() && (t.back() == '.' || std::isspace(static_cast<unsigned char>(t.back())))) t.pop_back();
  // "Rep 1st and 2nd rows 3 times more", "... alternately": the label says how many rows.
  static const std::regex how_often(R"(\s+(?:\d+\s+times|twice|once|alternately|inclusive|incl)(?:\s+more)?(?:\s+again)?$)");
  if (t.size() > 200) return std::nullopt;  // a repeat of rows is said in a few words
  t = std::regex_replace(t, how_often, "");
  constexpr std::string_view nouns[] = {"rows ", "row ", "rounds ", "round ", "rnds ", "rnd "};
  for (std::string_view verb : {"repeat ", "rep ", "work as ", "work ", "same as ", "as "}) {
    if (t.rfind(verb, 0) != 0) continue;
    std::string rest = t.substr(verb.size());
    for (std::string_view noun : nouns) {
      if (rest.rfind(noun, 0) == 0) {
        rest = rest.substr(noun.size());
        // "repeat rows 1-4 once more", "... twice" are not read: once, where it stands.
        return numbers(rest, problem);
      }
    }
    // "as 1st and 2nd rows"
    if (rest.empty() || !std::isdigit(static_cast<unsigned char>(rest[0]))) return std::nullopt;
    for (std::string_view noun : nouns) {
      const std::string_view word = noun.substr(0, noun.size() - 1);
      if (rest.size() > word.size() && rest.compare(rest.size() - word.size(), word.size(), word) == 0 &&
          rest[rest.size() - word.size() - 1] == ' ')
        return numbers(without_ordinals(rest.substr(0, rest.size() - word.size())), problem);
    }
    return std::nullopt;
  }
  return std::nullopt;
}

// A label with no separator, "Row 1 (RS)   P2, k3" or "Row 15 P2, k6": the numbers (each
// run of digits bounded by a separator, so a long number cannot backtrack), a
// side perhaps, then words that read as a row (else it is no label: "Rows 1-4 form the
// pattern" is a note).
std::optional<Label> loose_label(std::string_view line, std::size_t after) {
  static const std::regex head(
      R"(^\s*(\d+(?:\s*(?:,|&|-)\s*(?:and\s+)?\d+|\s+(?:and|to)\s+\d+)*)\s*(\((?:rs|ws|right side|wrong side)\)|\[(?:rs|ws)\]|rs|ws)?\s*(\((?:and )?(?:every|all)[^)]*\)|(?:and\s+)?(?:all|every)\s+(?:other\s+|following\s+)?(?:ws|rs|wrong side|right side)\s+rows?)?\s*[:.]*\s+)");
  const std::string rest = lower(line.substr(after, std::min<std::size_t>(line.size() - after, 200)));
  std::smatch m;
  if (!std::regex_search(rest, m, head)) return std::nullopt;
  std::string problem;
  auto out = head_rows(m[1].str() + " " + m[3].str(), problem);
  if (!out) return std::nullopt;
  if (m[2].matched) out->side = m[2].str().find('w') != std::string::npos ? Side::wrong : Side::right;
  out->body = std::string(trim(line.substr(after + static_cast<std::size_t>(m.length(0)))));
  side_in_body(*out);
  // A row that reads, a repeat of rows, or one whose first stitch reads (the rest may be
  // the glossary's abbreviations).
  std::string again;
  const std::string first = out->body.substr(0, out->body.find(','));
  const bool starts_as_row = out->body.find(',') != std::string::npos &&
                             (first.find_first_of("*([") != std::string::npos ||
                              std::holds_alternative<Reading>(read_stitch(normalise(first))));
  if (out->body.empty() ||
      (parse_row(out->body, {}, false).index() != 0 && !repeated_rows(out->body, again) && !starts_as_row))
    return std::nullopt;
  return out;
}

// "Row 1 (RS): ...", "Rnds 2 and 4: ...", "Rows 1, 3 (WS). ...", and the vintage
// "1st row.-K 2, p 2." and "2nd and 4th rows (wrong side): ..." (the line's typography
// already plain, so an em dash is "-").
std::optional<Label> label(std::string_view line, std::string& problem) {
  const std::string l = lower(line);
  std::size_t after = 0;
  if (noun_at(l, 0, after)) {
    for (std::size_t sep : separators(l, after)) {
      std::string attempt;
      auto out = head_rows(l.substr(after, sep - after), attempt);
      if (!out) {
        if (!attempt.empty() && sep == l.find(':', after)) problem = attempt;
        if (!problem.empty()) return std::nullopt;
        continue;
      }
      out->body = std::string(trim(line.substr(body_start(l, sep))));
      side_in_body(*out);
      return out;
    }
    return loose_label(line, after);
  }
  // The ordinal form: numbers first, then the noun.
  if (l.empty() || !std::isdigit(static_cast<unsigned char>(l[0]))) return std::nullopt;
  for (std::size_t at = 1; at < l.size(); ++at) {
    if (!std::isalpha(static_cast<unsigned char>(l[at])) || std::isalpha(static_cast<unsigned char>(l[at - 1]))) continue;
    if (!noun_at(l, at, after)) continue;
    const std::string head = without_ordinals(l.substr(0, at));
    // What stands between the noun and the separator is a side mark or nothing.
    for (std::size_t sep : separators(l, after)) {
      std::string attempt;
      auto out = head_rows(head + " " + l.substr(after, sep - after), attempt);
      if (!out) continue;
      out->body = std::string(trim(line.substr(body_start(l, sep))));
      side_in_body(*out);
      return out;
    }
    return std::nullopt;
  }
  return std::nullopt;
}

// A trailing "(14 sts)": the stitch count the row leaves; "(multiple of 12 sts, plus 11)"
// and other notes in brackets at the end are dropped.
std::string without_count(std::string text, std::optional<int>& count) {
  std::string_view t = trim(text);
  // "..., purl to end. Turn work.": the turn is the row's end, as every row's is.
  for (bool more = true; more;) {
    more = false;
    while (!t.empty() && (t.back() == '.' || t.back() == ';' || t.back() == ',')) t = trim(t.substr(0, t.size() - 1)), more = true;
    for (std::string_view turn : {"turn work", "turn"}) {
      if (t.size() > turn.size() && lower(t.substr(t.size() - turn.size())) == turn &&
          !std::isalnum(static_cast<unsigned char>(t[t.size() - turn.size() - 1]))) {
        t = trim(t.substr(0, t.size() - turn.size()));
        more = true;
      }
    }
  }
  if (t.empty() || t.back() != ')') return std::string(t);
  const std::size_t open = t.rfind('(');
  if (open == std::string_view::npos) return std::string(t);
  const std::string inside = lower(trim(t.substr(open + 1, t.size() - open - 2)));
  int n = 0;
  const auto [end, ec] = std::from_chars(inside.data(), inside.data() + inside.size(), n);
  const std::string_view rest = trim(std::string_view(inside).substr(static_cast<std::size_t>(end - inside.data())));
  if (ec == std::errc() && (rest == "sts" || rest == "st" || rest == "stitches" || rest == "stitch")) {
    if (n >= 0) count = n;  // "(-3 sts)" says what the row took away, not what it leaves: a note
    return std::string(trim(t.substr(0, open)));
  }
  if (inside.rfind("multiple of", 0) == 0) return std::string(trim(t.substr(0, open)));
  return std::string(t);
}

bool is_fence(std::string_view line) { return line.substr(0, 3) == "```" || line.substr(0, 3) == "~~~"; }



// A paragraph that runs several rows together, "Cast on 34 sts. 1st ROW: K 2, ... 2nd
// ROW: P across row.": cut before each label that follows a full stop or a semicolon.
std::vector<std::string_view> paragraph_rows(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t from = 0;
  for (std::size_t i = 1; i + 2 < line.size(); ++i) {
    if ((line[i - 1] != '.' && line[i - 1] != ';' && line[i - 1] != ':') || line[i] != ' ') continue;
    std::size_t j = i;
    while (j < line.size() && line[j] == ' ') ++j;
    const std::string head = lower(line.substr(j, std::min<std::size_t>(line.size() - j, 24)));
    const bool sentence = line[i - 1] == '.' && head.rfind("repeat from", 0) != 0 && head.rfind("rep from", 0) != 0 &&
                          head.rfind("rep. from", 0) != 0;
    if (sentence && (head.rfind("repeat ", 0) == 0 || head.rfind("rep ", 0) == 0)) {  // "..., k 12. Repeat these 8 rows."
      out.push_back(trim(line.substr(from, i - from)));
      from = j;
      continue;
    }
    const bool noun = head.rfind("row", 0) == 0 || head.rfind("rnd", 0) == 0 || head.rfind("round", 0) == 0;
    const bool ordinal = !head.empty() && std::isdigit(static_cast<unsigned char>(head[0])) &&
                         (head.find(" row") != std::string::npos || head.find(" rnd") != std::string::npos ||
                          head.find(" round") != std::string::npos);
    if (!noun && !ordinal) continue;
    std::string problem;
    if (!label(line.substr(j, std::min<std::size_t>(line.size() - j, 300)), problem)) continue;
    out.push_back(trim(line.substr(from, i - from)));
    from = j;
  }
  out.push_back(trim(line.substr(from)));
  return out;
}

// "On WS rows, work sts as they appear", "All WS rows: purl": the text, if that is it.
std::optional<std::string> wrong_side_text(std::string_view line) {
  const std::string l = lower(line);
  for (std::string_view lead : {"on all ws rows", "on ws rows", "on wrong side rows", "on all wrong side rows", "all ws rows",
                                "every ws row", "ws rows", "all even rows", "even rows", "even-numbered rows",
                                "all even-numbered rows", "wrong side rows"}) {
    if (l.rfind(lead, 0) != 0) continue;
    std::size_t at = lead.size();
    while (at < l.size() && (l[at] == ':' || l[at] == ',' || l[at] == '-' || l[at] == ' ')) ++at;
    if (at == lead.size() || at >= l.size()) return std::nullopt;
    return std::string(trim(line.substr(at)));
  }
  return std::nullopt;
}

// The block's lines, plain: typography as ASCII, "»" bullets as line breaks, and a line
// that breaks off after a comma or a semicolon, or before "from *", joined to the next.
std::vector<std::pair<int, std::string>> plain_lines(std::string_view block) {
  std::vector<std::pair<int, std::string>> out;
  bool open = false;  // the last line broke off mid-row
  int line_number = 0;
  for (std::size_t start = 0; start <= block.size(); ++line_number) {
    const std::size_t end = std::min(block.find('\n', start), block.size());
    const std::string_view raw = block.substr(start, end - start);
    start = end + 1;
    std::string plain = typography_as_ascii(without_bullet(trim(raw)));
    for (std::size_t at; (at = plain.find("\u00BB")) != std::string::npos;) plain.replace(at, 2, "\n");
    std::size_t from = 0;
    for (std::size_t cut = 0; cut <= plain.size(); ++cut) {
      if (cut < plain.size() && plain[cut] != '\n') continue;
      const std::string piece(trim(std::string_view(plain).substr(from, cut - from)));
      from = cut + 1;
      if (piece.empty()) continue;
      const std::string low = lower(piece);
      std::string problem;
      const bool labelled = label(std::string_view(piece).substr(0, std::min<std::size_t>(piece.size(), 300)), problem).has_value();
      if (!out.empty() && !labelled && (open || low.rfind("from *", 0) == 0)) out.back().second += " " + piece;
      else out.emplace_back(line_number, piece);
      const std::string& last = out.back().second;
      std::string why;
      const auto l = label(std::string_view(last).substr(0, std::min<std::size_t>(last.size(), 300)), why);
      // "Row 1: (RS)" with its stitches on the next line.
      const bool bare_label = l && last.size() <= 300 && trim(l->body).empty();
      open = (bare_label || (!last.empty() && (last.back() == ',' || last.back() == ';'))) && last.size() < max_row_text_bytes;
    }
  }
  return out;
}


}  // namespace knitc::language::knitspeak_lines
