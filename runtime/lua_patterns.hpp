// Lua 5.4's string patterns (manual, section 6.4.1), matched with a step meter so a
// script's string.find, match, gmatch and gsub cost what they really do. Lua's own
// matcher backtracks without bound inside one C call, where no hook can stop it
// ("a*a*a*...b" is exponential); this one reports its steps as it goes, and the meter
// may throw to stop it. Pure C++: the bindings in sandbox_strings.cpp turn its results
// into Lua values and its SyntaxError into the messages Lua gives.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace knitc::runtime::lua_patterns {

inline constexpr int max_captures = 32;   // LUA_MAXCAPTURES
inline constexpr int max_depth = 200;     // nested pattern items (Lua's MAXCCALLS)
inline constexpr std::ptrdiff_t position_capture = -2;  // "()": the position, not a string
inline constexpr std::ptrdiff_t unfinished_capture = -1;

// A malformed pattern or a bad capture index; what() is Lua's own message for it.
class SyntaxError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Capture {
  std::size_t start = 0;           // offset in the subject
  std::ptrdiff_t length = unfinished_capture;  // bytes, or one of the two markers above
};

// Counts matching steps; `report` gets them in batches of `batch` and may throw (the
// caller's budget). A step is one attempt of one pattern item at one subject position.
class Meter {
 public:
  using Report = void (*)(void* context, std::uint64_t steps);
  Meter(Report report, void* context) : report_(report), context_(context) {}
  void step() {
    if (++pending_ == batch) flush();
  }
  void steps(std::uint64_t n) {
    pending_ += n;
    if (pending_ >= batch) flush();
  }
  void flush() {
    const std::uint64_t n = pending_;
    pending_ = 0;
    if (n != 0) report_(context_, n);
  }

 private:
  static constexpr std::uint64_t batch = 4096;
  Report report_;
  void* context_;
  std::uint64_t pending_ = 0;
};

// One pattern against one subject. `pattern` is without the leading '^' anchor (the
// callers strip it, as find and gsub treat it; gmatch keeps it as a plain character).
class Matcher {
 public:
  Matcher(std::string_view subject, std::string_view pattern, Meter& meter);

  // The end offset of a match starting at `start` (0 <= start <= subject size), or
  // nothing. Captures of the last successful match are then level() and capture(i).
  std::optional<std::size_t> match_at(std::size_t start);
  int level() const { return level_; }
  const Capture& capture(int i) const { return captures_[static_cast<std::size_t>(i)]; }

 private:
  const char* match(const char* s, const char* p);
  const char* class_end(const char* p) const;
  bool single_match(const char* s, const char* p, const char* ep) const;
  bool in_set(unsigned char c, const char* p, const char* ec) const;
  const char* max_expand(const char* s, const char* p, const char* ep);
  const char* min_expand(const char* s, const char* p, const char* ep);
  const char* start_capture(const char* s, const char* p, std::ptrdiff_t what);
  const char* end_capture(const char* s, const char* p);
  const char* match_balance(const char* s, const char* p);
  const char* match_back_reference(const char* s, int index);

  const char* src_;
  const char* src_end_;
  const char* pat_;
  const char* pat_end_;
  Meter& meter_;
  int depth_ = 0;
  int level_ = 0;
  std::array<Capture, max_captures> captures_{};
};

// The character classes of %a, %d, ... (`cl` is the letter; an upper-case letter is the
// complement; any other character stands for itself).
bool class_matches(unsigned char c, unsigned char cl);

// True if `pattern` has none of Lua's magic characters: find may then search plainly.
bool no_specials(std::string_view pattern);

// Plain search for `needle` in `haystack` from `from`, as string.find(s, p, init, true).
std::optional<std::size_t> find_plain(std::string_view haystack, std::string_view needle, std::size_t from, Meter& meter);

}  // namespace knitc::runtime::lua_patterns
