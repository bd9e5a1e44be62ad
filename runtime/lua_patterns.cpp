#include "lua_patterns.hpp"

#include <cctype>
#include <cstring>
#include <string>

namespace knitc::runtime::lua_patterns {

namespace {

constexpr char escape = '%';

}  // namespace

bool class_matches(unsigned char c, unsigned char cl) {
  bool yes = false;
  switch (std::tolower(cl)) {
    case 'a': yes = std::isalpha(c) != 0; break;
    case 'c': yes = std::iscntrl(c) != 0; break;
    case 'd': yes = std::isdigit(c) != 0; break;
    case 'g': yes = std::isgraph(c) != 0; break;
    case 'l': yes = std::islower(c) != 0; break;
    case 'p': yes = std::ispunct(c) != 0; break;
    case 's': yes = std::isspace(c) != 0; break;
    case 'u': yes = std::isupper(c) != 0; break;
    case 'w': yes = std::isalnum(c) != 0; break;
    case 'x': yes = std::isxdigit(c) != 0; break;
    default: return cl == c;  // %. and the like: the character itself
  }
  return std::isupper(cl) != 0 ? !yes : yes;
}

bool no_specials(std::string_view pattern) {
  return pattern.find_first_of(std::string_view("^$*+?.([%-")) == std::string_view::npos;
}

std::optional<std::size_t> find_plain(std::string_view haystack, std::string_view needle, std::size_t from, Meter& meter) {
  if (needle.empty()) return from;
  if (needle.size() > haystack.size() - from) return std::nullopt;
  const char* at = haystack.data() + from;
  const char* const last = haystack.data() + haystack.size() - needle.size();  // the last place it can start
  while (at <= last) {
    const auto* hit = static_cast<const char*>(std::memchr(at, needle[0], static_cast<std::size_t>(last - at) + 1));
    meter.steps(static_cast<std::uint64_t>((hit != nullptr ? hit : last) - at) / 16 + 1);
    if (hit == nullptr) return std::nullopt;
    meter.steps(needle.size() / 16 + 1);
    if (std::memcmp(hit + 1, needle.data() + 1, needle.size() - 1) == 0)
      return static_cast<std::size_t>(hit - haystack.data());
    at = hit + 1;
  }
  return std::nullopt;
}

Matcher::Matcher(std::string_view subject, std::string_view pattern, Meter& meter)
    : src_(subject.data()),
      src_end_(subject.data() + subject.size()),
      pat_(pattern.data()),
      pat_end_(pattern.data() + pattern.size()),
      meter_(meter) {}

std::optional<std::size_t> Matcher::match_at(std::size_t start) {
  meter_.steps(2);  // setting out from a new position
  level_ = 0;
  depth_ = 0;
  const char* end = match(src_ + start, pat_);
  if (end == nullptr) return std::nullopt;
  return static_cast<std::size_t>(end - src_);
}

// The end of the single-character class at p: one character, %x, or a [set].
const char* Matcher::class_end(const char* p) const {
  const char c = *p++;
  if (c == escape) {
    if (p >= pat_end_) throw SyntaxError("malformed pattern (ends with '%')");
    return p + 1;
  }
  if (c == '[') {
    if (p < pat_end_ && *p == '^') ++p;
    // The first character of a set is always a member, even ']'.
    do {
      if (p >= pat_end_) throw SyntaxError("malformed pattern (missing ']')");
      const char d = *p++;
      if (d == escape && p < pat_end_) ++p;
    } while (p >= pat_end_ || *p != ']');
    return p + 1;
  }
  return p;
}

// c against the set [ ... ] that starts at p and whose ']' is at ec.
bool Matcher::in_set(unsigned char c, const char* p, const char* ec) const {
  bool member = true;
  if (*(p + 1) == '^') {
    member = false;
    ++p;
  }
  while (++p < ec) {
    if (*p == escape) {
      ++p;
      if (class_matches(c, static_cast<unsigned char>(*p))) return member;
    } else if (*(p + 1) == '-' && p + 2 < ec) {
      p += 2;
      if (static_cast<unsigned char>(*(p - 2)) <= c && c <= static_cast<unsigned char>(*p)) return member;
    } else if (static_cast<unsigned char>(*p) == c) {
      return member;
    }
  }
  return !member;
}

bool Matcher::single_match(const char* s, const char* p, const char* ep) const {
  if (s >= src_end_) return false;
  const auto c = static_cast<unsigned char>(*s);
  switch (*p) {
    case '.': return true;
    case escape: return class_matches(c, static_cast<unsigned char>(*(p + 1)));
    case '[': return in_set(c, p, ep - 1);
    default: return static_cast<unsigned char>(*p) == c;
  }
}

const char* Matcher::max_expand(const char* s, const char* p, const char* ep) {
  std::ptrdiff_t i = 0;
  while (single_match(s + i, p, ep)) {
    ++i;
    meter_.step();
  }
  // Longest first, then shorter, until the rest of the pattern matches.
  for (; i >= 0; --i) {
    if (const char* end = match(s + i, ep + 1)) return end;
  }
  return nullptr;
}

const char* Matcher::min_expand(const char* s, const char* p, const char* ep) {
  for (;;) {
    if (const char* end = match(s, ep + 1)) return end;
    if (!single_match(s, p, ep)) return nullptr;
    ++s;
  }
}

const char* Matcher::start_capture(const char* s, const char* p, std::ptrdiff_t what) {
  if (level_ >= max_captures) throw SyntaxError("too many captures");
  captures_[static_cast<std::size_t>(level_)] = {static_cast<std::size_t>(s - src_), what};
  ++level_;
  const char* end = match(s, p);
  if (end == nullptr) --level_;
  return end;
}

const char* Matcher::end_capture(const char* s, const char* p) {
  int open = level_ - 1;
  while (open >= 0 && captures_[static_cast<std::size_t>(open)].length != unfinished_capture) --open;
  if (open < 0) throw SyntaxError("invalid pattern capture");
  Capture& c = captures_[static_cast<std::size_t>(open)];
  c.length = (s - src_) - static_cast<std::ptrdiff_t>(c.start);
  const char* end = match(s, p);
  if (end == nullptr) c.length = unfinished_capture;
  return end;
}

const char* Matcher::match_balance(const char* s, const char* p) {
  if (p >= pat_end_ - 1) throw SyntaxError("malformed pattern (missing arguments to '%b')");
  const char open = *p, close = *(p + 1);
  if ((s < src_end_ ? *s : '\0') != open) return nullptr;
  int depth = 1;
  while (++s < src_end_) {
    meter_.step();
    if (*s == close) {
      if (--depth == 0) return s + 1;
    } else if (*s == open) {
      ++depth;
    }
  }
  return nullptr;
}

const char* Matcher::match_back_reference(const char* s, int index) {
  const int i = index - '1';
  if (i < 0 || i >= level_ || captures_[static_cast<std::size_t>(i)].length == unfinished_capture)
    throw SyntaxError("invalid capture index %" + std::to_string(i + 1));
  const Capture& c = captures_[static_cast<std::size_t>(i)];
  if (c.length < 0) return nullptr;  // a position capture matches no text
  const auto length = static_cast<std::size_t>(c.length);
  meter_.steps(length / 16 + 1);
  if (static_cast<std::size_t>(src_end_ - s) >= length && std::memcmp(src_ + c.start, s, length) == 0) return s + length;
  return nullptr;
}

const char* Matcher::match(const char* s, const char* p) {
  if (++depth_ > max_depth) throw SyntaxError("pattern too complex");
  struct Leave {
    int& depth;
    ~Leave() { --depth; }
  } leave{depth_};
  for (;;) {  // each `continue` moves on to the next pattern item at the same depth
    meter_.step();
    if (p == pat_end_) return s;
    switch (*p) {
      case '(':
        if (p + 1 < pat_end_ && *(p + 1) == ')') return start_capture(s, p + 2, position_capture);
        return start_capture(s, p + 1, unfinished_capture);
      case ')': return end_capture(s, p + 1);
      case '$':
        if (p + 1 == pat_end_) return s == src_end_ ? s : nullptr;
        break;  // a '$' inside the pattern is an ordinary character
      case escape: {
        const char next = p + 1 < pat_end_ ? *(p + 1) : '\0';
        if (next == 'b') {
          s = match_balance(s, p + 2);
          if (s == nullptr) return nullptr;
          p += 4;
          continue;
        }
        if (next == 'f') {
          p += 2;
          if (p >= pat_end_ || *p != '[') throw SyntaxError("missing '[' after '%f' in pattern");
          const char* ep = class_end(p);
          const auto before = static_cast<unsigned char>(s == src_ ? '\0' : *(s - 1));
          const auto here = static_cast<unsigned char>(s < src_end_ ? *s : '\0');
          if (!in_set(before, p, ep - 1) && in_set(here, p, ep - 1)) {
            p = ep;
            continue;
          }
          return nullptr;
        }
        if (next >= '0' && next <= '9') {
          s = match_back_reference(s, next);
          if (s == nullptr) return nullptr;
          p += 2;
          continue;
        }
        break;  // %a, %., ...: a single-character class
      }
      default: break;
    }
    const char* ep = class_end(p);
    const char quantifier = ep < pat_end_ ? *ep : '\0';
    if (!single_match(s, p, ep)) {
      if (quantifier == '*' || quantifier == '?' || quantifier == '-') {  // zero of them will do
        p = ep + 1;
        continue;
      }
      return nullptr;
    }
    switch (quantifier) {
      case '?':
        if (const char* end = match(s + 1, ep + 1)) return end;
        p = ep + 1;
        continue;
      case '+': return max_expand(s + 1, p, ep);
      case '*': return max_expand(s, p, ep);
      case '-': return min_expand(s, p, ep);
      default:
        ++s;
        p = ep;
        continue;
    }
  }
}

}  // namespace knitc::runtime::lua_patterns
