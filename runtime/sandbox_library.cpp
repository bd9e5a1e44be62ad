// The base and coroutine functions the sandbox replaces: the ones that catch errors
// (a stop must not be caught), that could run code outside the budget (finalisers), or
// whose order would change from run to run (pairs and next over hashed keys).
#include <algorithm>
#include <cstring>
#include <vector>

#include "sandbox.hpp"

namespace knitc::runtime {

namespace {

constexpr std::uint64_t thread_cost = 1000;  // a new coroutine's instructions may never reach its hook

// --- pcall and xpcall: as Lua's, but a stop or a memory error is raised again.

int finish_protected(lua_State* L, int status, lua_KContext extra) {
  if (status != LUA_OK && status != LUA_YIELD) {
    raise_if_stopped(L, status);
    lua_pushboolean(L, 0);
    lua_pushvalue(L, -2);
    return 2;
  }
  return lua_gettop(L) - static_cast<int>(extra);
}

int protected_call(lua_State* L) {
  luaL_checkany(L, 1);
  lua_pushboolean(L, 1);  // the first result when all goes well
  lua_insert(L, 1);
  const int status = lua_pcallk(L, lua_gettop(L) - 2, LUA_MULTRET, 0, 0, finish_protected);
  return finish_protected(L, status, 0);
}

int protected_call_with_handler(lua_State* L) {
  const int n = lua_gettop(L);
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushboolean(L, 1);
  lua_pushvalue(L, 1);
  lua_rotate(L, 3, 2);  // true and the function go above the handler, below the arguments
  const int status = lua_pcallk(L, n - 2, LUA_MULTRET, 2, 2, finish_protected);
  return finish_protected(L, status, 2);
}

// --- setmetatable without finalisers: __gc runs with hooks off, also at lua_close.

int set_metatable(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const int t = lua_type(L, 2);
  luaL_argexpected(L, t == LUA_TNIL || t == LUA_TTABLE, 2, "nil or table");
  if (t == LUA_TTABLE) {
    lua_pushliteral(L, "__gc");
    if (lua_rawget(L, 2) != LUA_TNIL)
      luaL_error(L, "a metatable with __gc: finalisers are not allowed in patterns (they would run outside the "
                    "script's time budget); drop the __gc field");
    lua_pop(L, 1);
  }
  if (luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL) luaL_error(L, "cannot change a protected metatable");
  lua_settop(L, 2);
  lua_setmetatable(L, 1);
  return 1;
}

// --- pairs and next in a fixed order: the keys sorted, booleans, then numbers, then
// strings. Lua's own order follows string hashes seeded from the clock and addresses.

constexpr const char* order_cache = "knitc.key_order";  // registry: table -> {keys, at}

int key_rank(int type) { return type == LUA_TBOOLEAN ? 0 : type == LUA_TNUMBER ? 1 : 2; }

// a < b for two keys on the stack, both booleans, numbers or strings.
bool key_less(lua_State* L, int a, int b) {
  const int ta = lua_type(L, a), tb = lua_type(L, b);
  if (key_rank(ta) != key_rank(tb)) return key_rank(ta) < key_rank(tb);
  if (ta == LUA_TBOOLEAN) return lua_toboolean(L, a) < lua_toboolean(L, b);
  if (ta == LUA_TNUMBER) {
    if (lua_isinteger(L, a) && lua_isinteger(L, b)) return lua_tointeger(L, a) < lua_tointeger(L, b);
    const long double x = lua_isinteger(L, a) ? static_cast<long double>(lua_tointeger(L, a)) : lua_tonumber(L, a);
    const long double y = lua_isinteger(L, b) ? static_cast<long double>(lua_tointeger(L, b)) : lua_tonumber(L, b);
    return x < y;
  }
  std::size_t la = 0, lb = 0;
  const char* sa = lua_tolstring(L, a, &la);
  const char* sb = lua_tolstring(L, b, &lb);
  const int c = std::memcmp(sa, sb, std::min(la, lb));
  return c != 0 ? c < 0 : la < lb;
}

// Pushes the snapshot {keys = {k1, k2, ...}, at = {[k] = i}} of table `t`'s keys, sorted,
// and caches it for the traversal.
void push_key_order(lua_State* L, int t) {
  lua_createtable(L, 0, 0);
  const int keys = lua_gettop(L);
  lua_Integer n = 0;
  lua_pushnil(L);
  while (lua_next(L, t) != 0) {
    lua_pop(L, 1);
    const int type = lua_type(L, -1);
    if (type != LUA_TBOOLEAN && type != LUA_TNUMBER && type != LUA_TSTRING)
      luaL_error(L, "pairs/next over a table with a %s as a key: such keys have no order that stays the same from run "
                    "to run; keep them in a list and use ipairs", luaL_typename(L, -1));
    lua_pushvalue(L, -1);
    lua_rawseti(L, keys, ++n);
  }
  charge(L, static_cast<std::uint64_t>(n) * 4);
  // Sort keys[1..n] by index: the sort moves indices, the values stay on the table.
  std::vector<lua_Integer> order(static_cast<std::size_t>(n));
  for (lua_Integer i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i + 1;
  std::uint64_t comparisons = 0;
  std::stable_sort(order.begin(), order.end(), [&](lua_Integer a, lua_Integer b) {
    lua_rawgeti(L, keys, a);
    lua_rawgeti(L, keys, b);
    const bool less = key_less(L, -2, -1);
    lua_pop(L, 2);
    ++comparisons;
    return less;
  });
  charge(L, comparisons);
  lua_createtable(L, static_cast<int>(std::min<lua_Integer>(n, 1 << 20)), 0);
  const int sorted = lua_gettop(L);
  lua_createtable(L, 0, static_cast<int>(std::min<lua_Integer>(n, 1 << 20)));
  const int at = lua_gettop(L);
  for (lua_Integer i = 0; i < n; ++i) {
    lua_rawgeti(L, keys, order[static_cast<std::size_t>(i)]);
    lua_pushvalue(L, -1);
    lua_rawseti(L, sorted, i + 1);
    lua_pushinteger(L, i + 1);
    lua_rawset(L, at);
  }
  lua_createtable(L, 0, 2);
  lua_insert(L, sorted);  // the snapshot goes below sorted and at
  const int snapshot = sorted;
  lua_setfield(L, snapshot, "at");
  lua_setfield(L, snapshot, "keys");
  lua_remove(L, keys);
  // cache[t] = snapshot
  lua_getfield(L, LUA_REGISTRYINDEX, order_cache);
  lua_pushvalue(L, t);
  lua_pushvalue(L, -3);
  lua_rawset(L, -3);
  lua_pop(L, 1);
}

// The position of `key` in the snapshot at `snapshot`, or 0.
lua_Integer position(lua_State* L, int snapshot, int key) {
  if (!lua_istable(L, snapshot)) return 0;
  lua_getfield(L, snapshot, "at");
  lua_pushvalue(L, key);
  lua_rawget(L, -2);
  const lua_Integer at = lua_tointeger(L, -1);
  lua_pop(L, 2);
  return at;
}

int ordered_next(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_settop(L, 2);
  lua_Integer from = 0;  // the position of the key given; 0 for the first
  if (lua_isnil(L, 2)) {
    push_key_order(L, 1);  // a traversal starts: a new snapshot
  } else {
    lua_getfield(L, LUA_REGISTRYINDEX, order_cache);
    lua_pushvalue(L, 1);
    lua_rawget(L, -2);
    lua_remove(L, -2);
    from = position(L, lua_gettop(L), 2);
    if (from == 0) {  // no snapshot holds the key: next started mid-way, or keys were added
      lua_pop(L, 1);
      push_key_order(L, 1);
      from = position(L, lua_gettop(L), 2);
      if (from == 0) luaL_error(L, "invalid key to 'next'");
    }
  }
  lua_getfield(L, -1, "keys");
  const int keys = lua_gettop(L);
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, keys));
  for (lua_Integer i = from + 1; i <= n; ++i) {
    lua_rawgeti(L, keys, i);
    lua_pushvalue(L, -1);
    if (lua_rawget(L, 1) != LUA_TNIL) return 2;  // a key cleared during the traversal is passed over
    lua_pop(L, 2);
  }
  lua_pushnil(L);
  return 1;
}

int ordered_pairs(lua_State* L) {
  luaL_checkany(L, 1);
  if (luaL_getmetafield(L, 1, "__pairs") != LUA_TNIL) {  // the table's own iteration
    lua_pushvalue(L, 1);
    lua_call(L, 1, 3);
    return 3;
  }
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_pushcfunction(L, ordered_next);
  lua_pushvalue(L, 1);
  lua_pushnil(L);
  return 3;
}

// --- coroutines: the running thread is known (for the hook), a new one is charged,
// and a stop inside one is raised again in its resumer.

int coroutine_state(lua_State* L, lua_State* co) {  // 0 running, 1 suspended, 2 normal, 3 dead
  if (L == co) return 0;
  switch (lua_status(co)) {
    case LUA_YIELD: return 1;
    case LUA_OK: {
      lua_Debug ar;
      if (lua_getstack(co, 0, &ar) != 0) return 2;  // it resumed another
      return lua_gettop(co) == 0 ? 3 : 1;           // finished, or not started
    }
    default: return 3;  // stopped by an error
  }
}

// Resumes co with `narg` arguments from L's top; pushes its results (or the error) on L
// and returns how many, or -1 after an error.
int resume(lua_State* L, lua_State* co, int narg) {
  const int state = coroutine_state(L, co);
  if (state != 1) {
    lua_pushfstring(L, "cannot resume %s coroutine", state == 3 ? "dead" : "non-suspended");
    return -1;
  }
  if (!lua_checkstack(co, narg)) {
    lua_pushliteral(L, "too many arguments to resume");
    return -1;
  }
  // A resume and its yield cost about 600 instructions' time: Lua built as C++ yields by
  // throwing an exception.
  charge(L, 600);
  lua_xmove(L, co, narg);
  int results = 0;
  int status = LUA_OK;
  {
    Running running(L, co);
    status = lua_resume(co, L, narg, &results);
  }
  if (status == LUA_OK || status == LUA_YIELD) {
    if (!lua_checkstack(L, results + 1)) {
      lua_pop(co, results);
      lua_pushliteral(L, "too many results to resume");
      return -1;
    }
    lua_xmove(co, L, results);
    return results;
  }
  lua_xmove(co, L, 1);  // the error object
  raise_if_stopped(L, status);
  return -1;
}

int coroutine_create(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  charge(L, thread_cost);
  lua_State* co = lua_newthread(L);
  lua_pushvalue(L, 1);
  lua_xmove(L, co, 1);
  return 1;
}

int coroutine_resume(lua_State* L) {
  lua_State* co = lua_tothread(L, 1);
  luaL_argexpected(L, co != nullptr, 1, "coroutine");
  const int r = resume(L, co, lua_gettop(L) - 1);
  if (r < 0) {
    lua_pushboolean(L, 0);
    lua_insert(L, -2);
    return 2;
  }
  lua_pushboolean(L, 1);
  lua_insert(L, -(r + 1));
  return r + 1;
}

int close_thread(lua_State* co, lua_State* L) {
#if LUA_VERSION_RELEASE_NUM >= 50406
  return lua_closethread(co, L);
#else
  (void)L;
  return lua_resetthread(co);
#endif
}

int wrapped_call(lua_State* L) {
  lua_State* co = lua_tothread(L, lua_upvalueindex(1));
  const int r = resume(L, co, lua_gettop(L));
  if (r >= 0) return r;
  const int status = lua_status(co);
  if (status != LUA_OK && status != LUA_YIELD) {  // an error in the coroutine: close it
    int closed = LUA_OK;
    {
      Running running(L, co);
      closed = close_thread(co, L);
    }
    if (closed != LUA_OK) lua_xmove(co, L, 1);  // a newer error from a __close
    raise_if_stopped(L, closed);
  }
  if (lua_type(L, -1) == LUA_TSTRING) {  // where the error was raised, as coroutine.wrap says it
    luaL_where(L, 1);
    lua_insert(L, -2);
    lua_concat(L, 2);
  }
  return lua_error(L);
}

int coroutine_wrap(lua_State* L) {
  coroutine_create(L);
  lua_pushcclosure(L, wrapped_call, 1);
  return 1;
}

int coroutine_close(lua_State* L) {
  lua_State* co = lua_tothread(L, 1);
  luaL_argexpected(L, co != nullptr, 1, "coroutine");
  const int state = coroutine_state(L, co);
  if (state != 1 && state != 3) {
    return luaL_error(L, "cannot close a %s coroutine", state == 0 ? "running" : "normal");
  }
  int status = LUA_OK;
  {
    Running running(L, co);
    status = close_thread(co, L);
  }
  if (status == LUA_OK) {
    lua_pushboolean(L, 1);
    return 1;
  }
  lua_xmove(co, L, 1);
  raise_if_stopped(L, status);
  lua_pushboolean(L, 0);
  lua_insert(L, -2);
  return 2;
}

void set(lua_State* L, const char* library, const char* name, lua_CFunction f) {
  if (library == nullptr) {
    lua_pushcfunction(L, f);
    lua_setglobal(L, name);
    return;
  }
  lua_getglobal(L, library);
  lua_pushcfunction(L, f);
  lua_setfield(L, -2, name);
  lua_pop(L, 1);
}

}  // namespace

void open_budgeted_library(lua_State* L) {
  // Weak keys: a snapshot of a table's key order goes when the table does.
  lua_createtable(L, 0, 0);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "k");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_setfield(L, LUA_REGISTRYINDEX, order_cache);

  struct Replacement {
    const char* library;  // nullptr: a global
    const char* name;
    lua_CFunction function;
  };
  static const Replacement replacements[] = {
      {nullptr, "pcall", protected_call},
      {nullptr, "xpcall", protected_call_with_handler},
      {nullptr, "setmetatable", set_metatable},
      {nullptr, "next", ordered_next},
      {nullptr, "pairs", ordered_pairs},
      {LUA_COLIBNAME, "create", coroutine_create},
      {LUA_COLIBNAME, "resume", coroutine_resume},
      {LUA_COLIBNAME, "wrap", coroutine_wrap},
      {LUA_COLIBNAME, "close", coroutine_close},
  };
  for (const Replacement& r : replacements) set(L, r.library, r.name, r.function);
  open_budgeted_tables(L);
  open_budgeted_strings(L);
}

}  // namespace knitc::runtime
