// The table library's loops, budgeted. Lua's own loop inside one C call over a length
// that a __len metamethod may make anything (table.concat over 2^60 empty strings,
// table.insert at 1 of a "table" of 2^40), where no hook runs. These work as the
// manual says, charge every step before they take it, and read the length once.
// table.sort is a stable merge sort: Lua's picks pivots from the clock for long arrays,
// so equal elements could land differently from run to run.
#include <algorithm>
#include <climits>
#include <vector>

#include "sandbox.hpp"

namespace knitc::runtime {

namespace {

enum Access { read = 1, write = 2, length = 4 };

// The metatable `n` slots down has `key` (raw): pushes the key's value.
bool has_field(lua_State* L, const char* key, int n) {
  lua_pushstring(L, key);
  return lua_rawget(L, -n) != LUA_TNIL;
}

// A table, or anything whose metatable gives what the operation needs.
void check_table(lua_State* L, int arg, int what) {
  if (lua_type(L, arg) == LUA_TTABLE) return;
  int n = 1;  // the metatable and the fields looked up, to pop
  if (lua_getmetatable(L, arg) != 0 && ((what & read) == 0 || has_field(L, "__index", ++n)) &&
      ((what & write) == 0 || has_field(L, "__newindex", ++n)) && ((what & length) == 0 || has_field(L, "__len", ++n))) {
    lua_pop(L, n);
    return;
  }
  luaL_checktype(L, arg, LUA_TTABLE);  // raises the usual message
}

lua_Integer length_of(lua_State* L, int arg, int what) {
  check_table(L, arg, what | length);
  return luaL_len(L, arg);
}

std::uint64_t span(lua_Integer from, lua_Integer to) {  // to - from + 1, or 0
  return to < from ? 0 : static_cast<std::uint64_t>(to) - static_cast<std::uint64_t>(from) + 1;
}

int concat(lua_State* L) {
  lua_Integer last = length_of(L, 1, read);
  std::size_t separator_length = 0;
  const char* separator = luaL_optlstring(L, 2, "", &separator_length);
  lua_Integer i = luaL_optinteger(L, 3, 1);
  last = luaL_opt(L, luaL_checkinteger, 4, last);
  charge(L, span(i, last));
  luaL_Buffer b;
  luaL_buffinit(L, &b);
  for (; i <= last; ++i) {
    lua_geti(L, 1, i);
    if (lua_isstring(L, -1) == 0)
      luaL_error(L, "invalid value (at index %I) in table for 'concat'", static_cast<LUAI_UACINT>(i));
    luaL_addvalue(&b);
    if (i == last) break;  // last may be LUA_MAXINTEGER
    luaL_addlstring(&b, separator, separator_length);
  }
  luaL_pushresult(&b);
  return 1;
}

int insert(lua_State* L) {
  const lua_Integer end = length_of(L, 1, read | write) + 1;  // the first empty slot
  lua_Integer at = end;
  switch (lua_gettop(L)) {
    case 2: break;
    case 3: {
      at = luaL_checkinteger(L, 2);
      luaL_argcheck(L, static_cast<lua_Unsigned>(at) - 1u < static_cast<lua_Unsigned>(end), 2, "position out of bounds");
      charge(L, span(at, end));
      for (lua_Integer i = end; i > at; --i) {  // move up the elements after it
        lua_geti(L, 1, i - 1);
        lua_seti(L, 1, i);
      }
      break;
    }
    default: return luaL_error(L, "wrong number of arguments to 'insert'");
  }
  lua_seti(L, 1, at);
  return 0;
}

int remove(lua_State* L) {
  const lua_Integer size = length_of(L, 1, read | write);
  lua_Integer at = luaL_optinteger(L, 2, size);
  if (lua_gettop(L) >= 2 && at != size)
    luaL_argcheck(L, static_cast<lua_Unsigned>(at) - 1u <= static_cast<lua_Unsigned>(size), 2, "position out of bounds");
  charge(L, span(at, size));
  lua_geti(L, 1, at);
  for (; at < size; ++at) {
    lua_geti(L, 1, at + 1);
    lua_seti(L, 1, at);
  }
  lua_pushnil(L);
  lua_seti(L, 1, at);
  return 1;
}

int move(lua_State* L) {
  const lua_Integer from = luaL_checkinteger(L, 2);
  const lua_Integer to_end = luaL_checkinteger(L, 3);
  const lua_Integer to = luaL_checkinteger(L, 4);
  const int target = lua_isnoneornil(L, 5) ? 1 : 5;
  check_table(L, 1, read);
  check_table(L, target, write);
  if (to_end >= from) {
    luaL_argcheck(L, from > 0 || to_end < LUA_MAXINTEGER + from, 3, "too many elements to move");
    const lua_Integer n = to_end - from + 1;
    luaL_argcheck(L, to <= LUA_MAXINTEGER - n + 1, 4, "destination wrap around");
    charge(L, static_cast<std::uint64_t>(n));
    if (to > to_end || to > from || (target != 1 && lua_compare(L, 1, target, LUA_OPEQ) == 0)) {
      for (lua_Integer i = 0; i < n; ++i) {
        lua_geti(L, 1, from + i);
        lua_seti(L, target, to + i);
      }
    } else {  // overlapping, to the right: from the end
      for (lua_Integer i = n - 1; i >= 0; --i) {
        lua_geti(L, 1, from + i);
        lua_seti(L, target, to + i);
      }
    }
  }
  lua_pushvalue(L, target);
  return 1;
}

int unpack(lua_State* L) {
  lua_Integer i = luaL_optinteger(L, 2, 1);
  const lua_Integer last = lua_isnoneornil(L, 3) ? luaL_len(L, 1) : luaL_checkinteger(L, 3);
  if (i > last) return 0;
  const lua_Unsigned n = static_cast<lua_Unsigned>(last) - static_cast<lua_Unsigned>(i);
  if (n >= static_cast<lua_Unsigned>(INT_MAX) || lua_checkstack(L, static_cast<int>(n + 1)) == 0)
    return luaL_error(L, "too many results to unpack");
  charge(L, n + 1);
  for (; i < last; ++i) lua_geti(L, 1, i);
  lua_geti(L, 1, last);
  return static_cast<int>(n + 1);
}

int sort(lua_State* L) {
  const lua_Integer n = length_of(L, 1, read | write);
  if (n <= 1) return 0;
  luaL_argcheck(L, n < INT_MAX, 1, "array too big");
  const bool custom = !lua_isnoneornil(L, 2);
  if (custom) luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_settop(L, 2);
  charge(L, static_cast<std::uint64_t>(n));
  const auto count = static_cast<std::size_t>(n);
  hold(L, count * sizeof(lua_Integer));  // the order below
  struct Release {
    SandboxState& s;
    std::size_t bytes;
    ~Release() { s.host_bytes -= bytes; }
  } release{sandbox_of(L), count * sizeof(lua_Integer)};
  lua_createtable(L, static_cast<int>(std::min<lua_Integer>(n, 1 << 20)), 0);  // the values, read once
  const int values = lua_gettop(L);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, 1, i);
    lua_rawseti(L, values, i);
  }
  std::vector<lua_Integer> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = static_cast<lua_Integer>(i) + 1;
  std::uint64_t comparisons = 0;
  std::stable_sort(order.begin(), order.end(), [&](lua_Integer a, lua_Integer b) {
    if ((++comparisons & 1023) == 0) charge(L, 1024);
    if (custom) {
      lua_pushvalue(L, 2);
      lua_rawgeti(L, values, a);
      lua_rawgeti(L, values, b);
      lua_call(L, 2, 1);
    } else {
      lua_rawgeti(L, values, a);
      lua_rawgeti(L, values, b);
      const bool less = lua_compare(L, -2, -1, LUA_OPLT) != 0;
      lua_pop(L, 2);
      lua_pushboolean(L, less ? 1 : 0);
    }
    const bool less = lua_toboolean(L, -1) != 0;
    lua_pop(L, 1);
    return less;
  });
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, values, order[static_cast<std::size_t>(i - 1)]);
    lua_seti(L, 1, i);
  }
  return 0;
}

}  // namespace

void open_budgeted_tables(lua_State* L) {
  static const luaL_Reg functions[] = {
      {"concat", concat}, {"insert", insert}, {"remove", remove}, {"move", move},
      {"unpack", unpack}, {"sort", sort},     {nullptr, nullptr},
  };
  lua_getglobal(L, LUA_TABLIBNAME);
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}

}  // namespace knitc::runtime
