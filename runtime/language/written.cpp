// Written instructions parsed: tokens, then a recursive-descent parser of sequences,
// groups, repeats and stitches with their counts and yarns. One idea over 400 lines: the
// grammar of a written row, whose productions call each other; working a parsed row
// across the live stitches is worked.cpp.
#include "language/written.hpp"

#include "language/spelling.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace knitc::language {

namespace {

enum class Kind { word, star, comma, semicolon, open, close, end };

struct Token {
  Kind kind;
  std::string_view text;
  char bracket = 0;  // '(' or '[' for open and close
};

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    switch (c) {
      case '*': out.push_back({Kind::star, s.substr(i, 1)}); ++i; continue;
      case ',': out.push_back({Kind::comma, s.substr(i, 1)}); ++i; continue;
      case ';': out.push_back({Kind::semicolon, s.substr(i, 1)}); ++i; continue;
      case '(': case '[': out.push_back({Kind::open, s.substr(i, 1), c}); ++i; continue;
      case ')': case ']': out.push_back({Kind::close, s.substr(i, 1), c == ')' ? '(' : '['}); ++i; continue;
      default: break;
    }
    const std::size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) && std::string_view("*,;()[]").find(s[i]) == std::string_view::npos) ++i;
    out.push_back({Kind::word, s.substr(start, i - start)});
  }
  // A sentence's full stop at the very end is the knitter's, not a stitch.
  if (!out.empty() && out.back().kind == Kind::word && out.back().text.back() == '.') {
    out.back().text.remove_suffix(1);
    if (out.back().text.empty()) out.pop_back();
  }
  out.push_back({Kind::end, {}});
  return out;
}

std::optional<int> whole(std::string_view s) {
  int v = 0;
  if (s.empty() || s.size() > 6) return std::nullopt;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string join(std::span<const std::string_view> words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + std::string(w);
  return out;
}

// "; did you mean k2tog?" when a known name is close, else where to look.
std::string stitch_hint(const std::string& written) {
  const std::string nearest = nearest_stitch_name(written);
  // As nearest_stitch_name does, measure the start only: a megabyte of text must not cost
  // a megabyte times a name.
  const std::string_view start = std::string_view(written).substr(0, 48);
  const int distance = edit_distance(start, nearest);
  if (written.size() <= 48 && distance <= std::max<int>(2, static_cast<int>(start.size()) / 3))
    return "; did you mean " + nearest + "?";
  return "; knitc does not know it yet (knitc reference lists the stitches it knows)";
}

class Parser {
 public:
  Parser(std::string_view text, std::span<const std::string> yarns, bool hints = true)
      : text_(text), normal_(normalise(text)), side_(leading_side(normal_)), tokens_(tokenize(normal_)), yarns_(yarns),
        hints_(hints) {}

  // "(WS) k2, p2", "RS: k2, p2": a side printed before the stitches, taken off.
  static std::optional<Side> leading_side(std::string& text) {
    const std::string low = lower(text);
    for (const auto& [mark, side] : {std::pair{"(rs)", Side::right}, {"(ws)", Side::wrong}, {"rs:", Side::right},
                                     {"ws:", Side::wrong}, {"(right side)", Side::right}, {"(wrong side)", Side::wrong}}) {
      const std::size_t at = low.find_first_not_of(" \t");
      if (at == std::string::npos || low.compare(at, std::string_view(mark).size(), mark) != 0) continue;
      text.erase(0, at + std::string_view(mark).size());
      return side;
    }
    return std::nullopt;
  }

  std::variant<RowText, TextError> row() {
    // Brackets first: an unclosed group would otherwise read as a strange stitch.
    std::vector<char> open;
    for (const Token& t : tokens_) {
      if (t.kind == Kind::open) open.push_back(t.bracket);
      if (t.kind == Kind::close) {
        if (open.empty()) return fail(std::string("'") + std::string(t.text) + "' without a matching opening bracket");
        if (open.back() != t.bracket) return fail(std::string("'") + open.back() + "' is closed by '" + std::string(t.text) + "'");
        open.pop_back();
      }
    }
    if (!open.empty()) return fail(std::string("'") + open.back() + "' is never closed");
    RowText r;
    r.side = side_;
    Appear appear = side_ ? Appear::no : as_they_appear(text_);
    if (appear == Appear::no) appear = as_they_appear(normal_);
    if (appear != Appear::no) {
      r.as_they_appear = true;
      r.opposite = appear == Appear::opposite;
      return r;
    }
    r.before = sequence();
    if (open_) {
      if (peek().kind == Kind::star) return fail("a row can have one repeat only: \"*...; rep from *\" or \"... to end\"");
      split_open_repeat(r);
    } else if (peek().kind == Kind::star) {
      next();
      Sequence star = sequence();
      if (open_) return fail("a repeat inside a *repeat; write one repeat only");
      const bool closed = peek().kind == Kind::star;
      if (closed) next();  // "*k2, p2*; rep from *"
      if (closed && counted_words()) {
        // "*K2, P2* 11 times": the stars bracket a group worked that many times.
        Element group;
        group.is_group = true;
        group.body = std::move(star);
        group.count = group_count();
        if (error_) return *error_;
        r.before.push_back(std::move(group));
        Sequence rest = sequence();
        if (open_) open_->element += r.before.size();
        r.before.insert(r.before.end(), std::make_move_iterator(rest.begin()), std::make_move_iterator(rest.end()));
        if (open_) split_open_repeat(r);
      } else {
        r.star = std::move(star);
        // "; rep from *" as the core language writes it, or printed ", repeat from *".
        if (peek().kind == Kind::semicolon || peek().kind == Kind::comma) next();
        else if (peek().kind != Kind::word && !(closed && peek().kind == Kind::end))
          return fail("a *repeat needs \"; rep from *\" after it");
        const bool said = peek().kind == Kind::word && (is_repeat_word(peek().text) || lower(peek().text) == "to");
        if (closed && !said) {
          // "*k4, k3tog, yo, p1* k2": the stars close the repeat, and the row's end follows.
          r.after = sequence();
        } else if (!repeat_clause(r)) {
          return *error_;
        } else if (peek().kind == Kind::word) {
          r.after = sequence();  // "*k1, p8 repeat* k3"
        }
        if (peek().kind == Kind::comma || peek().kind == Kind::semicolon) {
          next();
          r.after = sequence();
        }
      }
    }
    while (peek().kind == Kind::semicolon || peek().kind == Kind::comma) next();  // "...k5;" closing the row
    if (error_) return *error_;
    if (peek().kind == Kind::close) return fail(std::string("'") + std::string(peek().text) + "' without a matching opening bracket");
    if (peek().kind == Kind::star) return fail("a row can have one *repeat only");
    if (peek().kind != Kind::end) return fail("unexpected '" + std::string(peek().text) + "'");
    if (r.before.empty() && !r.star && r.after.empty()) return fail("no stitches; give stitches such as \"k\"");
    if (r.star && r.star->empty()) return fail("the *repeat has no stitches");
    return r;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  const Token& next() { return tokens_[pos_++]; }
  TextError fail(std::string message) {
    if (!error_) error_ = TextError{std::move(message)};
    return *error_;
  }

  // "st", "sts", "stitch", "stitches" (and the typed "stitchs"), any case.
  static bool stitch_words(std::string_view w) {
    const std::string l = lower(w);
    return l == "st" || l == "sts" || l == "stitch" || l == "stitches" || l == "stitchs";
  }

  static bool is_repeat_word(std::string_view w) {
    const std::string l = lower(w);
    return l == "rep" || l == "repeat";
  }

  // "rep from *" [to end | across | to last N st(s)]
  bool repeat_clause(RowText& r) {
    std::vector<std::string> words;
    while (peek().kind == Kind::word) words.push_back(lower(next().text));
    if (words.size() >= 2 && is_repeat_word(words[0]) && words[1] == "from" && peek().kind == Kind::star) {
      next();
      words.clear();
      const std::size_t rest = pos_;
      while (peek().kind == Kind::word) words.push_back(lower(next().text));
      // "rep from * end B2", a comma left out: the row's closing stitches follow.
      if (!words.empty() && (words[0] == "end" || std::holds_alternative<Reading>(read_stitch(words[0])))) {
        pos_ = rest;
        return true;
      }
    } else if (!words.empty() && is_repeat_word(words[0]) && (words.size() == 1 || words[1] == "to")) {
      words.erase(words.begin());  // "*yo, p1* rep to end": the stars say where from
      if (words.empty() && peek().kind == Kind::star) next();  // "*k1, p8 repeat* k3"
    } else if (!words.empty() && words[0] == "to") {
      // "*K1, P1* across" (read "to end"): the stars and how far
    } else {
      fail("after \";\" write \"rep from *\"");
      return false;
    }
    if (words.empty() || (words.size() == 1 && words[0] == "across")) return true;
    if (const auto to = to_clause(words)) {
      r.to_last = *to;
      return true;
    }
    if (!error_)
      fail("\"rep from * " + join(std::vector<std::string_view>(words.begin(), words.end())) +
           "\" is not understood; write \"rep from *\", \"rep from * to end\" or \"rep from * to last N sts, ...\"");
    return false;
  }

  // How far a repeat goes: "to end [of row | round | rnd]" (0 stitches after it),
  // "to last [N] st(s)", "to N st(s) before end [of ...]"; nothing if the words say
  // something else.
  static std::optional<int> to_clause(std::span<const std::string> w) {
    // "to the last 4 sts"
    std::vector<std::string> kept;
    for (const std::string& x : w)
      if (x != "the") kept.push_back(x);
    w = kept;
    auto end_of = [](std::span<const std::string> rest) {
      return rest.empty() || (rest.size() == 2 && rest[0] == "of" &&
                              (rest[1] == "row" || rest[1] == "round" || rest[1] == "rnd" || rest[1] == "needle"));
    };
    if (w.size() < 2 || w[0] != "to") return std::nullopt;
    if (w[1] == "end" && end_of(w.subspan(2))) return 0;
    if (w[1] == "last" && w.size() == 4 && whole(w[2]) && stitch_words(w[3])) return whole(w[2]);
    if (w[1] == "last" && w.size() == 3 && stitch_words(w[2])) return 1;
    if (w[1] == "last" && w.size() == 3 && whole(w[2])) return whole(w[2]);  // "to last 6: p4"
    if (w.size() >= 5 && whole(w[1]) && stitch_words(w[2]) && w[3] == "before" && w[4] == "end" && end_of(w.subspan(5)))
      return whole(w[1]);
    return std::nullopt;
  }

  enum class Appear { no, same, opposite };

  // "knit the knit sts and purl the purl sts" (same) and "p over k and k over p"
  // (opposite, as moss stitch is worked), however it is phrased; "work each stitch as it
  // appears - knit the knits, purl the purls" says it twice.
  static Appear as_they_appear(std::string_view text) {
    std::string t = lower(text);
    // "... as they appear and yo's P": a yarn over shows as a knit stitch, so purling it
    // from the wrong side is working it as it appears.
    for (std::string_view yos : {" and yo's p", " and yos p", " and yo's purl", " and purl the yo's", " and purl the yos",
                                 ", purling the yo's", ", purling the yos", " and purl yo's", " and purl yos"}) {
      const auto at = t.find(yos);
      if (at != std::string::npos) t.erase(at, yos.size());
    }
    static constexpr std::string_view same[] = {
        "knit the knit sts and purl the purl sts", "knit the knit stitches and purl the purl stitches",
        "knit the knit stitches, purl the purl stitches", "knit the knit sts, purl the purl sts",
        "knit the knits and purl the purls", "knit the knits, purl the purls", "k the k sts and p the p sts",
        "k the knit sts and p the purl sts", "k the k and p the p", "knit over knit, purl over purl",
        "knit over knit and purl over purl", "purl over purl, knit over knit", "purl over purl and knit over knit",
        "k over k, p over p", "k over k and p over p", "work sts as they appear", "work the sts as they appear",
        "work all sts as they appear", "work each st as it appears", "work each stitch as it appears",
        "work stitches as they appear", "work as appears", "work in pattern as established", "work sts as set"};
    static constexpr std::string_view opposite[] = {
        "p over k and k over p", "k over p and p over k", "p over k, k over p", "k over p, p over k",
        "purl the knit sts and knit the purl sts", "knit the purl sts and purl the knit sts",
        "purl the knits and knit the purls", "knit the purls and purl the knits", "k the p sts and p the k sts",
        "p the k sts and k the p sts", "purl over knit and knit over purl", "knit over purl and purl over knit"};
    auto rest_is_empty = [](std::string_view r) {
      return r.find_first_not_of(" \t.,;-") == std::string_view::npos;
    };
    // The row's words are a phrase of `list`, or that phrase twice in other words.
    auto says = [&](std::span<const std::string_view> list) {
      std::string_view v = t;
      while (!v.empty() && std::string_view(" \t.,;-").find(v.front()) != std::string_view::npos) v.remove_prefix(1);
      for (std::string_view phrase : list) {
        if (v.substr(0, phrase.size()) != phrase) continue;
        std::string_view rest = v.substr(phrase.size());
        if (rest_is_empty(rest)) return true;
        while (!rest.empty() && std::string_view(" \t.,;-").find(rest.front()) != std::string_view::npos) rest.remove_prefix(1);
        for (std::string_view again : list)
          if (rest.substr(0, again.size()) == again && rest_is_empty(rest.substr(again.size()))) return true;
      }
      return false;
    };
    if (says(same)) return Appear::same;
    if (says(opposite)) return Appear::opposite;
    return Appear::no;
  }

  // An open repeat ("(p2, k2) to 3 sts before end", "k to end") is the row's *repeat:
  // what comes before it is worked once first, what follows it once last. "k2, p2 to
  // end" repeats the whole run, as knitters mean it; "k1, p to end" only the p.
  void split_open_repeat(RowText& r) {
    Sequence all = std::move(r.before);
    const std::size_t at = open_->element;
    const std::size_t first = open_->whole_run ? 0 : at;
    r.before.assign(std::make_move_iterator(all.begin()), std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(first)));
    r.star = Sequence(std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(first)),
                      std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(at) + 1));
    r.after.assign(std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(at) + 1), std::make_move_iterator(all.end()));
    if (open_->to_last > 0 || !r.after.empty()) r.to_last = open_->to_last;
  }

  // Marks the element just added to `seq` as the open repeat, from the words after it.
  bool open_repeat(std::span<const std::string> clause, Sequence& seq, bool counted_stitch) {
    const auto to = to_clause(clause);
    if (!to) return false;
    if (depth_ > 0) {
      fail("\"" + join(std::vector<std::string_view>(clause.begin(), clause.end())) + "\" inside brackets; repeat the group instead");
      return true;
    }
    if (open_) {
      fail("a row can have one repeat only");
      return true;
    }
    const bool plain_run = std::none_of(seq.begin(), seq.end(), [](const Element& e) { return e.is_group; });
    open_ = Open{seq.size() - 1, *to, *to == 0 && counted_stitch && plain_run && seq.size() > 1};
    return true;
  }

  Sequence sequence() {
    Sequence seq;
    while (!error_) {
      const Token& t = peek();
      if (t.kind == Kind::comma) { next(); continue; }
      // "K to last 2 sts; K2 tog": a semicolon between stitches, not before "rep from *".
      if (t.kind == Kind::semicolon && pos_ + 1 < tokens_.size() && tokens_[pos_ + 1].kind == Kind::word &&
          !is_repeat_word(tokens_[pos_ + 1].text)) {
        next();
        continue;
      }
      if (t.kind == Kind::open) {
        if (depth_ >= max_depth) {
          fail("groups nested more than " + std::to_string(max_depth) + " deep");
          break;
        }
        next();
        ++depth_;
        Element group;
        group.is_group = true;
        group.body = sequence();
        --depth_;
        if (error_) break;
        if (peek().kind != Kind::close) {
          fail(std::string("'") + t.bracket + "' is never closed");
          break;
        }
        if (peek().bracket != t.bracket) {
          fail(std::string("'") + t.bracket + "' is closed by '" + std::string(peek().text) + "'");
          break;
        }
        next();
        if (group.body.empty()) {
          fail("an empty group \"()\"");
          break;
        }
        // "(k5, k2tog, yo) rep to last 5 sts": the repeat word says nothing more.
        if (peek().kind == Kind::word && is_repeat_word(peek().text) && pos_ + 1 < tokens_.size() &&
            tokens_[pos_ + 1].kind == Kind::word && lower(tokens_[pos_ + 1].text) == "to")
          next();
        if (peek().kind == Kind::word && lower(peek().text) == "to") {
          std::vector<std::string> clause;
          while (peek().kind == Kind::word) clause.push_back(lower(next().text));
          seq.push_back(std::move(group));
          if (!open_repeat(clause, seq, false))
            fail("\"" + join(std::vector<std::string_view>(clause.begin(), clause.end())) +
                 "\" after a group is not understood; write \"to end\" or \"to 3 sts before end\"");
          continue;
        }
        group.count = group_count();
        if (group.count > 0) seq.push_back(std::move(group));
        continue;
      }
      if (t.kind != Kind::word || is_repeat_word(t.text)) break;
      std::vector<std::string_view> words;
      while (peek().kind == Kind::word && (words.empty() || !is_repeat_word(peek().text))) words.push_back(next().text);
      // "p2 to end of round": the stitch, then how far it repeats.
      const auto to = std::find_if(words.begin(), words.end(), [](std::string_view w) { return lower(w) == "to"; });
      std::vector<std::string> clause;
      for (auto w = to; w != words.end(); ++w) clause.push_back(lower(*w));
      if (to != words.begin() && to != words.end() && to_clause(clause)) words.erase(to, words.end());
      else clause.clear();
      // "k 1, p 1 alternately": the two stitches, repeated across.
      const bool alternately = words.size() > 1 && lower(words.back()) == "alternately";
      if (alternately) words.pop_back();
      if (!item(words, seq)) break;
      if (alternately) {
        if (seq.size() < 2 || !clause.empty()) {
          fail("\"alternately\" follows the two stitches that alternate: \"k1, p1 alternately\"");
          break;
        }
        Element pair;
        pair.is_group = true;
        pair.body.assign(seq.end() - 2, seq.end());
        seq.erase(seq.end() - 2, seq.end());
        seq.push_back(std::move(pair));
        const std::string to_end[] = {"to", "end"};
        if (!open_repeat(to_end, seq, false)) fail("\"alternately\" is not understood here");
        if (error_) break;
        continue;
      }
      if (!clause.empty()) open_repeat(clause, seq, last_counted_);
      if (error_) break;
    }
    return seq;
  }

  // Whether the words next are a group's count ("11 times", "twice", "x3"), read no further.
  bool counted_words() const {
    std::vector<std::string> words;
    for (std::size_t i = pos_; i < tokens_.size() && tokens_[i].kind == Kind::word && words.size() < 3; ++i)
      words.push_back(lower(tokens_[i].text));
    if (words.empty()) return false;
    const std::string& a = words[0];
    if (a == "twice" || a == "once" || a == "thrice") return true;
    if (a.size() > 1 && a[0] == 'x' && whole(std::string_view(a).substr(1))) return true;
    if (a == "x" && words.size() > 1 && whole(words[1])) return true;
    return whole(a) && words.size() > 1 && (words[1] == "times" || words[1] == "time" || words[1] == "x");
  }

  // After a group: "x6", "x 6", "6x", "6 times", "twice", "once", or nothing (once).
  int group_count() {
    std::vector<std::string> words;
    std::size_t save = pos_;
    while (peek().kind == Kind::word) words.push_back(lower(next().text));
    std::optional<int> n;
    if (words.empty()) return 1;
    if (words.size() == 1 && words[0].size() > 1 && words[0][0] == 'x') n = whole(std::string_view(words[0]).substr(1));
    else if (words.size() == 1 && words[0].size() > 1 && words[0].back() == 'x') n = whole(std::string_view(words[0]).substr(0, words[0].size() - 1));
    else if (words.size() == 2 && words[0] == "x") n = whole(words[1]);
    else if (words.size() == 2 && words[1] == "x") n = whole(words[0]);
    else if (words.size() == 2 && (words[1] == "times" || words[1] == "time")) n = whole(words[0]);
    else if (words.size() == 1 && words[0] == "twice") n = 2;
    else if (words.size() == 1 && words[0] == "thrice") n = 3;
    else if (words.size() == 1 && words[0] == "once") n = 1;
    if (!n) {
      pos_ = save;
      fail("\"" + join(std::vector<std::string_view>(words.begin(), words.end())) +
           "\" after a group is not a repeat count; write x6 or 6 times");
      return 0;
    }
    if (*n < 1 || *n > max_count) {
      fail("a group repeated " + std::to_string(*n) + " times; the count must be from 1 to 100000");
      return 0;
    }
    return *n;
  }

  // One stitch: a name from the table, perhaps with a count on its first word
  // ("k2", "sl1 wyif"), perhaps followed by a declared yarn id ("k2 B").
  bool item(std::span<const std::string_view> words, Sequence& seq) {
    const std::string written = join(words);
    std::optional<int> yarn;
    if (words.size() > 1) {
      const auto it = std::find(yarns_.begin(), yarns_.end(), words.back());
      if (it != yarns_.end()) {
        yarn = static_cast<int>(it - yarns_.begin());
        words = words.first(words.size() - 1);
      }
    }
    // "sl1, k2tog, psso": passing the slipped stitch over makes the two one stitch.
    if (words.size() == 1 && (lower(words[0]) == "psso" || lower(words[0]) == "pass slipped stitch over")) return pass_over(seq);
    const std::string spelled = lower(join(words));
    if (is_marker(spelled)) return true;  // placed or slipped: no stitch is worked
    if (is_edge_stitch(spelled)) {
      Element e;
      e.stitch = {stitch_id("k"), yarn.value_or(-1), true};
      seq.push_back(e);
      last_counted_ = false;
      return true;
    }
    // "slip1, WYIF": a modifier on its own belongs to the stitch before it.
    if (words.size() == 1 && !seq.empty() && !seq.back().is_group && seq.back().count == 1) {
      for (std::string_view modifier : {"wyif", "wyib", "tbl", "kwise", "pwise"}) {
        if (spelled != modifier) continue;
        const auto with = read_stitch(std::string(stitch(seq.back().stitch.stitch).name) + " " + std::string(modifier));
        if (const auto* r = std::get_if<Reading>(&with)) {
          seq.back().stitch.stitch = r->stitch;
          return true;
        }
      }
    }
    // "keeping yarn at front, k5": a yarn over in some patterns, only the yarn's place in
    // others; knitc does not guess.
    if (words.size() == 1 && (spelled == "wyif" || spelled == "wyib")) {
      fail("'" + written + "' on its own goes with no stitch: write it with the stitch it belongs to (sl1 " + spelled +
           "), or yo where the yarn brought forward makes a yarn over");
      return false;
    }
    // "rep from *, end p3": what closes the row.
    if (words.size() > 1 && lower(words[0]) == "end") return item(words.subspan(1), seq);
    // "K last 2 sts": the stitch, that many times.
    if (words.size() == 4 && lower(words[1]) == "last" && whole(words[2]) && stitch_words(words[3]) &&
        std::holds_alternative<Reading>(read_stitch(words[0]))) {
      const std::size_t before = seq.size();
      const std::string_view one[] = {words[0]};
      if (!item(std::span<const std::string_view>(one), seq)) return false;
      if (seq.size() == before + 1 && !seq.back().is_group) seq.back().count = std::max(1, *whole(words[2]));
      return true;
    }
    // The stitch as printed: exact, squeezed ("K 2 tog"), or with a count run in ("sl1pw").
    const auto reading = read_stitch(words);
    if (const auto* a = std::get_if<Ambiguous>(&reading)) {
      fail(ambiguous_message(*a));
      return false;
    }
    std::optional<StitchId> id;
    int count = 1;
    bool explicit_count = false;
    if (const auto* r = std::get_if<Reading>(&reading)) {
      if (r->count_too_large) {
        fail("the count in '" + written + "' must be from 1 to 100000");
        return false;
      }
      id = r->stitch;
      count = r->count;
      explicit_count = r->count_written;
    }
    if (!id && words.size() > 1 && words.size() <= 8) {
      // "p2 C8L", a comma left out: two stitches that each read.
      for (std::size_t cut = 1; cut < words.size(); ++cut) {
        if (!std::holds_alternative<Reading>(read_stitch(words.first(cut))) ||
            !std::holds_alternative<Reading>(read_stitch(words.subspan(cut))))
          continue;
        return item(words.first(cut), seq) && item(words.subspan(cut), seq);
      }
    }
    if (!id) {
      // "k2 C" with C not declared: say so rather than call it an unknown stitch.
      const std::string_view last = words.back();
      if (!yarn && words.size() > 1 && std::isupper(static_cast<unsigned char>(last[0])) && !find_stitch(last)) {
        std::vector<std::string_view> rest(words.begin(), words.end() - 1);
        if (Parser(join(rest), {}).row().index() == 0) {
          fail("yarn '" + std::string(last) + "' in '" + written + "' was never declared; declare it in pattern{ yarns = ... }");
          return false;
        }
      }
      fail("unknown stitch '" + written + "'" + (hints_ ? stitch_hint(written) : std::string()));
      return false;
    }
    if (explicit_count && !language::words(*id).counted) {
      fail(std::string(stitch(*id).name) + " takes no count ('" + written + "'); repeat it with commas or a group");
      return false;
    }
    Element e;
    e.stitch = {*id, yarn.value_or(-1)};
    e.count = count;
    if (explicit_count && *id == stitch_id("bo")) {
      // "BO 3 sts": three come off, and the stitch the third is passed over stays on the
      // right needle, worked already: printed counts go on from the stitch after it.
      Element kept;
      kept.stitch = {stitch_id("k"), yarn.value_or(-1)};
      Element group;
      group.is_group = true;
      group.body = {e, kept};
      seq.push_back(group);
    } else {
      seq.push_back(e);
    }
    last_counted_ = explicit_count;
    return true;
  }

  // "psso" after "sl1, k1" or "sl1, k2tog": the two become skp (ssk) or sk2p.
  bool pass_over(Sequence& seq) {
    auto single = [](const Element& e, std::string_view name) {
      return !e.is_group && e.count == 1 && stitch(e.stitch.stitch).name == name;
    };
    if (seq.size() >= 2 && single(seq[seq.size() - 2], "sl wyib") &&
        (single(seq.back(), "k") || single(seq.back(), "k2tog"))) {
      const bool two = stitch(seq.back().stitch.stitch).name == "k2tog";
      seq.pop_back();
      seq.back().stitch.stitch = stitch_id(two ? "sk2p" : "ssk");
      return true;
    }
    fail("psso passes a slipped stitch over the one just worked: write it after \"sl1, k1\" or \"sl1, k2tog\"");
    return false;
  }

  std::string_view text_;
  std::string normal_;  // the text as normalise() spells it: what the tokens view
  std::optional<Side> side_;  // a side printed before the stitches
  std::vector<Token> tokens_;
  std::span<const std::string> yarns_;
  bool hints_ = true;
  std::size_t pos_ = 0;
  int depth_ = 0;
  bool last_counted_ = false;  // the last stitch read had a count written on it ("p2")
  struct Open {
    std::size_t element;  // the open repeat's element in the top-level sequence
    int to_last;          // stitches left after it, 0: to the end
    bool whole_run;       // "k2, p2 to end": the run from the row's start repeats
  };
  std::optional<Open> open_;
  static constexpr int max_depth = 16;  // knitters nest two or three; the bound keeps recursion shallow
  std::optional<TextError> error_;
};

}  // namespace

bool is_edge_stitch(std::string_view spelled) {
  const std::string l = lower(spelled);
  for (std::string_view edge : {"edge st", "edge stitch", "selvedge st", "selvedge stitch", "selvedge", "selvage st",
                                "selvage stitch", "selvage", "sel st", "sel s", "sel", "edge", "edge sts"})
    if (l == edge) return true;
  return false;
}

bool is_marker(std::string_view spelled) {
  const std::string l = lower(spelled);
  if (marker_word(l)) return true;
  for (std::string_view facing : {"rsf", "rs facing", "with rs facing", "wsf", "ws facing", "with ws facing"})
    if (l == facing) return true;
  return false;
}

std::string quote_row(std::string_view text) {
  constexpr std::size_t longest = 60;
  if (text.size() <= longest) return "\"" + std::string(text) + "\"";
  return "\"" + std::string(text.substr(0, longest)) + "...\"";
}

std::variant<RowText, TextError> parse_row(std::string_view text, std::span<const std::string> yarn_ids, bool hints) {
  if (text.size() > max_row_text_bytes)
    return TextError{"the row's text is " + std::to_string(text.size() >> 10) + " KiB; a row is at most " +
                     std::to_string(max_row_text_bytes >> 10) + " KiB of instructions"};
  if (auto split = split_at_markers(text)) {
    RowText row;
    for (MarkedText& m : *split) {
      MarkedPart part{{}, m.end, m.before};
      if (m.text.find_first_not_of(" \t") != std::string::npos) {
        auto parsed = Parser(m.text, yarn_ids, hints).row();
        if (auto* e = std::get_if<TextError>(&parsed)) return *e;
        part.text = std::move(std::get<RowText>(parsed));
      }
      if (part.text.side) {
        if (!row.parts.empty()) return TextError{"\"(RS)\" or \"(WS)\" belongs at the start of a row"};
        row.side = part.text.side;
        part.text.side.reset();
      }
      if (part.text.as_they_appear)
        return TextError{"stitches worked as they appear are not read between stitch markers yet; give the stitches"};
      row.parts.push_back(std::move(part));
    }
    if (std::all_of(row.parts.begin(), row.parts.end(),
                    [](const MarkedPart& p) { return p.text.before.empty() && !p.text.star && p.text.after.empty(); }))
      return TextError{"the row places, slips or works to markers but gives no stitches"};
    return row;
  }
  return Parser(text, yarn_ids, hints).row();
}

}  // namespace knitc::language
