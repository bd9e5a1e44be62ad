// string.rep, find, match, gmatch and gsub, budgeted: the matching is lua_patterns.cpp,
// which reports its steps; these bindings give its results the shape Lua's have.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "lua_patterns.hpp"
#include "sandbox.hpp"

namespace knitc::runtime {

namespace {

using lua_patterns::Matcher;
using lua_patterns::Meter;

// A matching step costs about two VM instructions' time.
void report_steps(void* context, std::uint64_t steps) { charge(static_cast<lua_State*>(context), 2 * steps); }

// A string position as Lua reads one: 1-based, negative from the end, clamped to 1.
std::size_t position(lua_Integer pos, std::size_t length) {
  if (pos > 0) return static_cast<std::size_t>(pos);
  if (pos == 0) return 1;
  if (pos < -static_cast<lua_Integer>(length)) return 1;
  return length + static_cast<std::size_t>(pos) + 1;
}

std::string_view string_arg(lua_State* L, int arg) {
  std::size_t length = 0;
  const char* s = luaL_checklstring(L, arg, &length);
  return {s, length};
}

// Pushes capture i of the last match of m over [start, end).
void push_capture(lua_State* L, const Matcher& m, std::string_view subject, int i, std::size_t start, std::size_t end) {
  if (i >= m.level()) {
    if (i != 0) luaL_error(L, "invalid capture index %%%d", i + 1);
    lua_pushlstring(L, subject.data() + start, end - start);  // the whole match
    return;
  }
  const lua_patterns::Capture& c = m.capture(i);
  if (c.length == lua_patterns::unfinished_capture) luaL_error(L, "unfinished capture");
  if (c.length == lua_patterns::position_capture) {
    lua_pushinteger(L, static_cast<lua_Integer>(c.start) + 1);
    return;
  }
  lua_pushlstring(L, subject.data() + c.start, static_cast<std::size_t>(c.length));
}

// Pushes every capture (or the whole match when there are none and `whole`).
int push_captures(lua_State* L, const Matcher& m, std::string_view subject, bool whole, std::size_t start, std::size_t end) {
  const int n = m.level() == 0 && whole ? 1 : m.level();
  luaL_checkstack(L, n, "too many captures");
  for (int i = 0; i < n; ++i) push_capture(L, m, subject, i, start, end);
  return n;
}

[[noreturn]] void syntax_error(lua_State* L, const lua_patterns::SyntaxError& e) {
  luaL_error(L, "%s", e.what());
  std::abort();
}

int find_or_match(lua_State* L, bool find) {
  const std::string_view s = string_arg(L, 1);
  std::string_view p = string_arg(L, 2);
  const std::size_t init = position(luaL_optinteger(L, 3, 1), s.size());
  if (init > s.size() + 1) {
    luaL_pushfail(L);
    return 1;
  }
  Meter meter(report_steps, L);
  if (find && (lua_toboolean(L, 4) != 0 || lua_patterns::no_specials(p))) {
    const auto at = lua_patterns::find_plain(s, p, init - 1, meter);
    meter.flush();
    if (at) {
      lua_pushinteger(L, static_cast<lua_Integer>(*at) + 1);
      lua_pushinteger(L, static_cast<lua_Integer>(*at + p.size()));
      return 2;
    }
    luaL_pushfail(L);
    return 1;
  }
  const bool anchored = !p.empty() && p.front() == '^';
  if (anchored) p.remove_prefix(1);
  try {
    Matcher m(s, p, meter);
    for (std::size_t start = init - 1;; ++start) {
      if (const auto end = m.match_at(start)) {
        meter.flush();
        if (!find) return push_captures(L, m, s, true, start, *end);
        lua_pushinteger(L, static_cast<lua_Integer>(start) + 1);
        lua_pushinteger(L, static_cast<lua_Integer>(*end));
        return push_captures(L, m, s, false, start, *end) + 2;
      }
      if (anchored || start >= s.size()) break;
    }
  } catch (const lua_patterns::SyntaxError& e) {
    syntax_error(L, e);
  }
  meter.flush();
  luaL_pushfail(L);
  return 1;
}

int find(lua_State* L) { return find_or_match(L, true); }
int match(lua_State* L) { return find_or_match(L, false); }

struct GmatchState {
  std::size_t next = 0;        // where the next search starts
  std::size_t last_end = 0;    // the end of the last match, so an empty match there is skipped
  bool matched = false;
};

int gmatch_step(lua_State* L) {
  const std::string_view s = string_arg(L, lua_upvalueindex(1));
  const std::string_view p = string_arg(L, lua_upvalueindex(2));  // '^' is a plain character here
  auto& state = *static_cast<GmatchState*>(lua_touserdata(L, lua_upvalueindex(3)));
  Meter meter(report_steps, L);
  try {
    Matcher m(s, p, meter);
    for (std::size_t start = state.next; start <= s.size(); ++start) {
      const auto end = m.match_at(start);
      if (end && !(state.matched && *end == state.last_end)) {
        meter.flush();
        state.next = state.last_end = *end;
        state.matched = true;
        return push_captures(L, m, s, true, start, *end);
      }
    }
  } catch (const lua_patterns::SyntaxError& e) {
    syntax_error(L, e);
  }
  meter.flush();
  state.next = s.size() + 1;
  return 0;
}

int gmatch(lua_State* L) {
  const std::string_view s = string_arg(L, 1);
  string_arg(L, 2);
  std::size_t start = position(luaL_optinteger(L, 3, 1), s.size()) - 1;
  if (start > s.size()) start = s.size() + 1;  // past the end: no match, the pattern not even read
  lua_settop(L, 2);
  auto* state = static_cast<GmatchState*>(lua_newuserdatauv(L, sizeof(GmatchState), 0));
  *state = GmatchState{start, 0, false};
  lua_pushcclosure(L, gmatch_step, 3);
  return 1;
}

// A replacement string with %0-%9 and %%.
void add_replacement(lua_State* L, luaL_Buffer& b, const Matcher& m, std::string_view s, std::size_t start,
                     std::size_t end) {
  std::size_t length = 0;
  const char* r = lua_tolstring(L, 3, &length);
  charge(L, length / 16 + 1);
  const char* const r_end = r + length;
  while (r < r_end) {
    const auto* percent = static_cast<const char*>(std::memchr(r, '%', static_cast<std::size_t>(r_end - r)));
    if (percent == nullptr) {
      luaL_addlstring(&b, r, static_cast<std::size_t>(r_end - r));
      break;
    }
    luaL_addlstring(&b, r, static_cast<std::size_t>(percent - r));
    const char c = percent + 1 < r_end ? percent[1] : '\0';
    if (c == '%') {
      luaL_addchar(&b, '%');
    } else if (c >= '0' && c <= '9') {
      if (c == '0') {
        luaL_addlstring(&b, s.data() + start, end - start);
      } else {
        push_capture(L, m, s, c - '1', start, end);
        luaL_tolstring(L, -1, nullptr);  // a position capture is a number
        lua_remove(L, -2);
        luaL_addvalue(&b);
      }
    } else {
      luaL_error(L, "invalid use of '%c' in replacement string", '%');
    }
    r = percent + 2;
  }
}

// Adds the replacement of one match; false if the match is kept as it was.
bool add_value(lua_State* L, luaL_Buffer& b, const Matcher& m, std::string_view s, std::size_t start, std::size_t end,
               int type) {
  switch (type) {
    case LUA_TFUNCTION: {
      lua_pushvalue(L, 3);
      const int n = push_captures(L, m, s, true, start, end);
      lua_call(L, n, 1);
      break;
    }
    case LUA_TTABLE:
      push_capture(L, m, s, 0, start, end);
      lua_gettable(L, 3);
      break;
    default:
      add_replacement(L, b, m, s, start, end);
      return true;
  }
  if (lua_toboolean(L, -1) == 0) {  // nil or false: keep the original text
    lua_pop(L, 1);
    luaL_addlstring(&b, s.data() + start, end - start);
    return false;
  }
  if (lua_isstring(L, -1) == 0) luaL_error(L, "invalid replacement value (a %s)", luaL_typename(L, -1));
  luaL_addvalue(&b);
  return true;
}

int gsub(lua_State* L) {
  const std::string_view s = string_arg(L, 1);
  std::string_view p = string_arg(L, 2);
  const int type = lua_type(L, 3);
  const lua_Integer max_n = luaL_optinteger(L, 4, static_cast<lua_Integer>(s.size()) + 1);
  luaL_argexpected(L, type == LUA_TNUMBER || type == LUA_TSTRING || type == LUA_TFUNCTION || type == LUA_TTABLE, 3,
                   "string/function/table");
  const bool anchored = !p.empty() && p.front() == '^';
  if (anchored) p.remove_prefix(1);
  luaL_Buffer b;
  luaL_buffinit(L, &b);
  Meter meter(report_steps, L);
  std::size_t at = 0;
  std::optional<std::size_t> last_end;
  lua_Integer n = 0;
  bool changed = false;
  try {
    Matcher m(s, p, meter);
    while (n < max_n) {
      const auto end = m.match_at(at);
      if (end && end != last_end) {
        meter.flush();
        ++n;
        changed = add_value(L, b, m, s, at, *end, type) || changed;
        at = *end;
        last_end = end;
      } else if (at < s.size()) {
        luaL_addchar(&b, s[at++]);
      } else {
        break;
      }
      if (anchored) break;
    }
  } catch (const lua_patterns::SyntaxError& e) {
    syntax_error(L, e);
  }
  meter.flush();
  if (!changed) {
    lua_pushvalue(L, 1);
  } else {
    luaL_addlstring(&b, s.data() + at, s.size() - at);
    luaL_pushresult(&b);
  }
  lua_pushinteger(L, n);
  return 2;
}

// string.rep without the loop over 2^50 empty copies, and refused before allocating
// when the result could not be a string of this sandbox.
int rep(lua_State* L) {
  const std::string_view s = string_arg(L, 1);
  const lua_Integer n = luaL_checkinteger(L, 2);
  std::size_t separator_length = 0;
  const char* separator = luaL_optlstring(L, 3, "", &separator_length);
  charge(L, 20);  // the call itself
  if (n <= 0 || s.size() + separator_length == 0) {
    lua_pushliteral(L, "");
    return 1;
  }
  const std::size_t limit = sandbox_of(L).limits.string_bytes;
  const auto copies = static_cast<std::uint64_t>(n);
  const std::uint64_t each = s.size() + separator_length;
  if (each > limit || copies > (limit + separator_length) / each) {
    const long double total = static_cast<long double>(each) * static_cast<long double>(copies);
    char mib[64];
    std::snprintf(mib, sizeof mib, " (string.rep of %.3Lg MiB)", total / (1 << 20));
    stop(L, Stop::string, mib);
  }
  const std::size_t total = static_cast<std::size_t>(copies * each) - separator_length;
  charge(L, copies / 8 + 1);  // the copies; the bytes are charged as they are allocated
  luaL_Buffer b;
  char* out = luaL_buffinitsize(L, &b, total);
  for (std::uint64_t i = 0; i < copies; ++i) {
    std::memcpy(out, s.data(), s.size());
    out += s.size();
    if (separator_length > 0 && i + 1 < copies) {
      std::memcpy(out, separator, separator_length);
      out += separator_length;
    }
  }
  luaL_pushresultsize(&b, total);
  return 1;
}

}  // namespace

void open_budgeted_strings(lua_State* L) {
  static const luaL_Reg functions[] = {
      {"find", find}, {"match", match}, {"gmatch", gmatch}, {"gsub", gsub}, {"rep", rep}, {nullptr, nullptr},
  };
  lua_getglobal(L, LUA_STRLIBNAME);
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}

}  // namespace knitc::runtime
