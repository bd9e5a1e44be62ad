#include "sandbox.hpp"

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <vector>

#include "stitches/stitches.hpp"

namespace knitc::runtime {

namespace {

constexpr int hook_every = 1000;  // instructions between count hooks

void* allocate(void* ud, void* ptr, std::size_t old_size, std::size_t new_size) {
  auto& s = *static_cast<SandboxState*>(ud);
  const std::size_t old_bytes = ptr != nullptr ? old_size : 0;  // else old_size is a type tag
  if (new_size == 0) {
    std::free(ptr);
    s.bytes_in_use -= old_bytes;
    return nullptr;
  }
  if (new_size > old_bytes && s.bytes_in_use - old_bytes + new_size > s.limits.memory_bytes) {
    s.out_of_memory = true;
    return nullptr;
  }
  void* block = std::realloc(ptr, new_size);
  if (block != nullptr) s.bytes_in_use = s.bytes_in_use - old_bytes + new_size;
  return block;
}

void count_hook(lua_State* L, lua_Debug* ar) {
  SandboxState& s = sandbox_of(L);
  if (lua_getinfo(L, "l", ar) != 0 && ar->currentline > 0) s.last_line = ar->currentline;
  s.instructions += hook_every;
  if (s.instructions > s.limits.instructions) {
    lua_pushfstring(L, "%s:%d: pattern ran too long (over %d million Lua instructions); look for a loop that never ends",
                    s.file.c_str(), s.last_line, static_cast<int>(s.limits.instructions / 1'000'000));
    lua_error(L);
  }
}

int print_to_stderr(lua_State* L) {
  const int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    std::size_t len = 0;
    const char* s = luaL_tolstring(L, i, &len);
    if (i > 1) std::fputc('\t', stderr);
    std::fwrite(s, 1, len, stderr);
    lua_pop(L, 1);
  }
  std::fputc('\n', stderr);
  return 0;
}

// load(chunk [, chunkname [, mode [, env]]]) for strings of text only.
int load_text(lua_State* L) {
  std::size_t len = 0;
  const char* chunk = luaL_checklstring(L, 1, &len);
  const char* name = luaL_optstring(L, 2, "=(load)");
  const bool has_env = !lua_isnone(L, 4);
  if (luaL_loadbufferx(L, chunk, len, name, "t") != LUA_OK) {
    luaL_pushfail(L);
    lua_insert(L, -2);
    return 2;
  }
  if (has_env) {
    lua_pushvalue(L, 4);
    if (lua_setupvalue(L, -2, 1) == nullptr) lua_pop(L, 1);
  }
  return 1;
}

// The pcall message handler: a non-string error object still gets a located message.
int message_handler(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING) return 1;
  // The innermost script line: level 1 is error() itself, a C function with no line.
  lua_Debug ar;
  int level = 1;
  while (lua_getstack(L, level, &ar) != 0 && lua_getinfo(L, "Sl", &ar) != 0 && ar.currentline <= 0) ++level;
  luaL_where(L, level);
  lua_pushstring(L, "error raised with a ");
  lua_pushstring(L, luaL_typename(L, 1));
  lua_pushstring(L, " value instead of a message; pass error() a string");
  lua_concat(L, 4);
  return 1;
}

// "attempt to call a nil value (global 'rows_')": the nearest global name, if one is close.
std::string global_hint(lua_State* L, const std::string& message) {
  const std::string marker = "(global '";
  const auto at = message.find(marker);
  if (at == std::string::npos || message.find("attempt to call a nil value") == std::string::npos) return "";
  const auto end = message.find('\'', at + marker.size());
  if (end == std::string::npos) return "";
  const std::string name = message.substr(at + marker.size(), end - at - marker.size());
  std::vector<std::string> names;
  lua_pushglobaltable(L);
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_type(L, -1) == LUA_TFUNCTION) names.emplace_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  std::sort(names.begin(), names.end());  // ties go to the first name, whatever the table order
  std::string best;
  int best_distance = 3;
  for (const auto& n : names) {
    const int d = edit_distance(name, n);
    if (d < best_distance) best_distance = d, best = n;
  }
  return best.empty() ? "" : "; did you mean " + best + "?";
}

}  // namespace

SandboxState& sandbox_of(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<SandboxState*>(ud);
}

lua_State* open_sandbox(SandboxState& state) {
  lua_State* L = lua_newstate(allocate, &state);
  if (L == nullptr) return nullptr;
  static const luaL_Reg libraries[] = {
      {LUA_GNAME, luaopen_base},       {LUA_TABLIBNAME, luaopen_table},
      {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},
      {LUA_UTF8LIBNAME, luaopen_utf8}, {LUA_COLIBNAME, luaopen_coroutine},
  };
  for (const luaL_Reg& lib : libraries) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  // Nothing that reaches files, bytecode or the collector's state.
  for (const char* name : {"dofile", "loadfile", "collectgarbage"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  lua_pushcfunction(L, load_text);
  lua_setglobal(L, "load");
  lua_pushcfunction(L, print_to_stderr);
  lua_setglobal(L, "print");
  lua_getglobal(L, LUA_STRLIBNAME);
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  lua_pop(L, 1);
  // math.random: the same numbers on every run.
  lua_getglobal(L, LUA_MATHLIBNAME);
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, state.seed);
  lua_call(L, 1, 0);
  lua_pop(L, 1);
  lua_sethook(L, count_hook, LUA_MASKCOUNT, hook_every);
  return L;
}

void run_chunk(lua_State* L, std::string_view source) {
  SandboxState& s = sandbox_of(L);
  const std::string chunk_name = "@" + s.file;
  int status = luaL_loadbufferx(L, source.data(), source.size(), chunk_name.c_str(), "t");
  if (status == LUA_OK) {
    lua_pushcfunction(L, message_handler);
    lua_insert(L, -2);
    status = lua_pcall(L, 0, 0, -2);
  }
  if (status == LUA_OK) return;
  if (s.out_of_memory || status == LUA_ERRMEM) {
    throw PatternError(s.file + ":" + std::to_string(s.last_line) + ": pattern used more than " +
                       std::to_string(s.limits.memory_bytes >> 20) +
                       " MiB of memory; look for a table that grows without end");
  }
  const char* message = lua_tostring(L, -1);
  if (message == nullptr) throw PatternError(s.file + ": unknown error");
  throw PatternError(message + global_hint(L, message));
}

}  // namespace knitc::runtime
