// Reading Lua values with errors located at the script's line.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "fields.hpp"
#include "script.hpp"

namespace knitc::runtime {

Script& script_of(lua_State* L) { return *static_cast<Script*>(sandbox_of(L).user); }

SourceLocation caller_location(lua_State* L) { return running_location(L); }

std::string text_of(lua_State* L, int index) {
  std::size_t length = 0;
  const char* s = lua_tolstring(L, index, &length);
  return s != nullptr ? std::string(s, length) : std::string();
}

void warn(lua_State* L, const SourceLocation& at, const std::string& message) {
  Script& s = script_of(L);
  if (s.warnings.size() >= max_warnings) {
    ++s.warnings_dropped;
    return;
  }
  std::string text = at.file + ":" + std::to_string(at.line) + ": warning: " + message;
  hold(L, text.size() + sizeof(std::string));
  s.warnings.push_back(std::move(text));
}

int caller_line(lua_State* L) { return caller_location(L).line; }

// The line of the pattern file itself that led to the innermost frame, if that frame is
// in a module: a designer calling a library function wants to see their own line too.
std::string called_from(lua_State* L, const SourceLocation& at) {
  const std::string& main = sandbox_of(L).file;
  if (at.file == main) return "";
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar) != 0; ++level) {
    if (lua_getinfo(L, "Sl", &ar) != 0 && ar.currentline > 0 && ar.source[0] == '@' && main == ar.source + 1)
      return " (called from " + main + ":" + std::to_string(ar.currentline) + ")";
  }
  return "";
}

SourceLocation pattern_location(lua_State* L, const SourceLocation& fallback) {
  const std::string& main = sandbox_of(L).file;
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar) != 0; ++level) {
    if (lua_getinfo(L, "Sl", &ar) != 0 && ar.currentline > 0 && ar.source[0] == '@' && main == ar.source + 1)
      return {main, ar.currentline};
  }
  return fallback;
}

void fail(lua_State* L, const std::string& message) { fail_at(L, caller_location(L), message); }

void fail_at(lua_State* L, const SourceLocation& at, const std::string& message) {
  const std::string text = at.file + ":" + std::to_string(at.line) + ": " + message + called_from(L, at);
  lua_pushlstring(L, text.data(), text.size());
  lua_error(L);
  std::abort();  // lua_error does not return
}

std::string show(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

std::optional<double> number_field(lua_State* L, int index, const std::string& table, const char* key) {
  lua_getfield(L, index, key);
  std::optional<double> result;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TNUMBER) fail(L, table + "." + key + " must be a number, not a " + luaL_typename(L, -1));
    result = lua_tonumber(L, -1);
  }
  lua_pop(L, 1);
  return result;
}

std::optional<std::string> string_field(lua_State* L, int index, const std::string& table, const char* key) {
  lua_getfield(L, index, key);
  std::optional<std::string> result;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING) fail(L, table + "." + key + " must be a string, not a " + luaL_typename(L, -1));
    result = text_of(L, -1);
  }
  lua_pop(L, 1);
  return result;
}

std::vector<std::string> sorted_keys(lua_State* L, int index, const std::string& table) {
  std::vector<std::string> keys;
  index = lua_absindex(L, index);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING) fail(L, table + " has a key that is not a name");
    if (static_cast<long long>(keys.size()) >= max_table_keys)
      fail(L, table + " has more than " + std::to_string(max_table_keys) + " keys");
    charge(L, 10);
    keys.push_back(text_of(L, -1));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

void only_known_keys(lua_State* L, int index, const std::string& table, std::string_view declared) {
  sorted_keys(L, index, table);  // every key must be a name
  only_known_fields(L, index, table, declared);
}

void only_known_fields(lua_State* L, int index, const std::string& table, std::string_view declared) {
  const std::vector<std::string> known = field_keys(declared);
  std::vector<std::string> named;
  index = lua_absindex(L, index);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    lua_pop(L, 1);
    charge(L, 10);
    if (lua_type(L, -1) != LUA_TSTRING) continue;
    if (static_cast<long long>(named.size()) >= max_table_keys)
      fail(L, table + " has more than " + std::to_string(max_table_keys) + " named fields");
    named.push_back(text_of(L, -1));
  }
  std::sort(named.begin(), named.end());  // the first unknown one, whatever the table order
  for (const std::string& key : named) {
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(L, "unknown field '" + printable(key, 100) + "' in " + table + "; known fields: " + list);
    }
  }
}

long long whole_number(lua_State* L, int arg, const std::string& what, long long lo, long long hi) {
  if (lua_type(L, arg) != LUA_TNUMBER) fail(L, what + " must be a whole number, not a " + luaL_typename(L, arg));
  int is_integer = 0;
  const long long v = lua_tointegerx(L, arg, &is_integer);  // 1e3 counts, 2.5 does not
  if (is_integer == 0) fail(L, what + " must be a whole number, not " + show(lua_tonumber(L, arg)));
  if (v < lo || v > hi)
    fail(L, what + " is " + std::to_string(v) + "; it must be from " + std::to_string(lo) + " to " + std::to_string(hi));
  return v;
}

int yarn_index(lua_State* L, const std::string& id) {
  const Script& s = script_of(L);
  for (std::size_t i = 0; i < s.yarn_ids.size(); ++i) {
    if (s.yarn_ids[i] == id) return static_cast<int>(i);
  }
  std::string list;
  for (const auto& y : s.yarn_ids) list += (list.empty() ? "" : ", ") + y;
  fail(L, "yarn '" + id + "' was never declared; declare it in pattern{ yarns = ... } (declared: " + list + ")");
}

}  // namespace knitc::runtime
