// Messages fit for a terminal: what a script says can reach stderr through an error, a
// warning or print(), and a hostile one would send escape sequences (that retitle the
// terminal, hide text, or worse) or a megabyte on one line.
#include <cstdint>
#include <string>

#include "runtime.hpp"

namespace knitc::runtime {

namespace {

constexpr std::size_t max_word = 200;  // bytes of one word kept whole (a long path fits)

// The length of the UTF-8 sequence at s[i], or 0 if it is not one.
std::size_t sequence_length(std::string_view s, std::size_t i, std::uint32_t& code) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n = 0;
  if (c < 0x80) {
    code = c;
    return 1;
  }
  if (c >= 0xc2 && c <= 0xdf) n = 2, code = c & 0x1fu;
  else if (c >= 0xe0 && c <= 0xef) n = 3, code = c & 0x0fu;
  else if (c >= 0xf0 && c <= 0xf4) n = 4, code = c & 0x07u;
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto d = static_cast<unsigned char>(s[i + k]);
    if ((d & 0xc0) != 0x80) return 0;
    code = (code << 6) | (d & 0x3fu);
  }
  const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < least[n] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

// Characters shown as escapes: controls (but newline and tab), and the invisible ones
// that reorder or hide text.
bool hidden(std::uint32_t code) {
  return (code < 0x20 && code != '\n' && code != '\t') || (code >= 0x7f && code <= 0x9f) ||
         (code >= 0x200b && code <= 0x200f) || (code >= 0x202a && code <= 0x202e) ||
         (code >= 0x2066 && code <= 0x2069) || code == 0xfeff;
}

std::string escaped(std::string_view s) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    std::uint32_t code = 0;
    const std::size_t n = sequence_length(s, i, code);
    if (n == 0) {  // not UTF-8: the byte as \xNN
      const auto c = static_cast<unsigned char>(s[i]);
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
      ++i;
      continue;
    }
    if (hidden(code)) {
      if (code < 0x100) {
        out += "\\x";
        out += hex[code >> 4];
        out += hex[code & 15];
      } else {
        out += "\\u{";
        for (int shift = 12; shift >= 0; shift -= 4) out += hex[(code >> shift) & 15];
        out += '}';
      }
    } else {
      out.append(s.substr(i, n));
    }
    i += n;
  }
  return out;
}

// The nearest UTF-8 character boundary at or before `at`.
std::size_t boundary(std::string_view s, std::size_t at) {
  while (at > 0 && at < s.size() && (static_cast<unsigned char>(s[at]) & 0xc0) == 0x80) --at;
  return at;
}

// Long words cut in their middle: the start and the end of each stay.
std::string short_words(std::string_view s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const bool space = s[i] == ' ' || s[i] == '\n' || s[i] == '\t';
    std::size_t j = i;
    while (j < s.size() && (s[j] == ' ' || s[j] == '\n' || s[j] == '\t') == space) ++j;
    const std::string_view word = s.substr(i, j - i);
    if (space || word.size() <= max_word) {
      out.append(word);
    } else {
      const std::size_t head = boundary(word, 120), tail = boundary(word, word.size() - 40);
      out.append(word.substr(0, head));
      out += "...[" + std::to_string(tail - head) + " bytes]...";
      out.append(word.substr(tail));
    }
    i = j;
  }
  return out;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out = escaped(short_words(text));
  if (out.size() <= max_bytes) return out;
  const std::size_t keep_tail = std::min<std::size_t>(200, max_bytes / 4);
  std::size_t head = boundary(out, max_bytes > keep_tail + 60 ? max_bytes - keep_tail - 60 : max_bytes / 2);
  std::size_t tail = boundary(out, out.size() - keep_tail);
  // Never cut an escape such as \x1b or \u{202e} in two (at most 8 bytes long).
  auto back_off = [&](std::size_t at) {
    const std::size_t slash = at == 0 ? std::string::npos : out.rfind('\\', at - 1);
    return slash != std::string::npos && at - slash < 8 ? slash : at;
  };
  head = back_off(head);
  tail = back_off(tail);
  return out.substr(0, head) + " ...[" + std::to_string(tail - head) + " bytes not shown]... " + out.substr(tail);
}

}  // namespace knitc::runtime
