#include "sandbox.hpp"

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <vector>

#include "language/words.hpp"

namespace knitc::runtime {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t large_block = 64u << 10;  // a block this large makes the hook come often
constexpr int large_every = 10;                 // instructions between hooks from then on
constexpr std::uint64_t bytes_per_unit = 16;  // allocation charged as work
// The error object of a stop: a light userdata needs no memory, which a stopped
// script no longer gets.
int stop_marker = 0;

void count_hook(lua_State* L, lua_Debug* ar);

void remember(SandboxState& s, const char* source, int line) {
  if (source != s.last_chunk) {  // copied only when the chunk changes
    s.last_chunk = source;
    s.last.file = source[0] == '@' ? std::string(source + 1) : s.file;
  }
  s.last.line = line;
}

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20); }

std::string stop_text(const SandboxState& s, Stop why, const SourceLocation& at, const std::string& detail) {
  const std::string where = at.file + ":" + std::to_string(std::max(at.line, 1)) + ": ";
  switch (why) {
    case Stop::work:
      return where + "pattern ran too long (over " + std::to_string(s.limits.instructions / 1'000'000) +
             " million Lua instructions, counting the work inside library calls); look for a loop that never ends";
    case Stop::time: {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", s.limits.seconds);
      return where + "pattern ran for more than " + seconds +
             " s; look for a loop that never ends, or for work on very long strings or tables";
    }
    case Stop::memory:
      return where + "pattern used more than " + mib(s.limits.memory_bytes) + " MiB of memory" + detail +
             "; look for a table or string that grows without end";
    case Stop::string:
      return where + "pattern made a string longer than " + mib(s.limits.string_bytes) + " MiB" + detail +
             ", the longest a pattern may make; build long texts from smaller pieces";
    case Stop::none: break;
  }
  return where + "pattern stopped";
}

// Marks the state stopped without raising: for the allocator, which cannot.
void mark_stopped(SandboxState& s, Stop why, const SourceLocation& at, const std::string& detail = "") {
  if (s.stop != Stop::none) return;
  s.stop = why;
  s.stop_message = stop_text(s, why, at, detail);
}

[[noreturn]] void raise_stop(lua_State* L) {
  lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);  // and again at the next instruction
  lua_pushlightuserdata(L, &stop_marker);
  lua_error(L);
  std::abort();  // lua_error does not return
}

// What a block of `size` bytes takes from malloc (glibc: an 8-byte header, 16-byte
// steps, 32 at least), so the cap bounds the memory the process really holds.
std::size_t footprint(std::size_t size) { return size == 0 ? 0 : std::max<std::size_t>(32, (size + 8 + 15) & ~std::size_t{15}); }

void* allocate(void* ud, void* ptr, std::size_t old_size, std::size_t new_size) {
  auto& s = *static_cast<SandboxState*>(ud);
  const std::size_t old_bytes = ptr != nullptr ? footprint(old_size) : 0;  // else old_size is a type tag
  if (new_size == 0) {
    std::free(ptr);
    s.bytes_in_use -= old_bytes;
    return nullptr;
  }
  const std::size_t new_bytes = footprint(new_size);
  if (new_bytes > old_bytes) {  // Lua assumes a block never fails to shrink: only growth is refused
    if (s.stop != Stop::none) return nullptr;
    const std::size_t growth = new_bytes - old_bytes;
    if (ptr == nullptr && old_size == LUA_TSTRING && new_size > s.limits.string_bytes + 64) {
      mark_stopped(s, Stop::string, s.last, " (" + mib(new_size) + " MiB)");
      return nullptr;
    }
    // Past the cap, a small step is let through and the hook comes at the next
    // instruction: it collects the garbage and, if the script still holds too much, stops
    // it there, with its line. A step past the slack is refused at once (Lua collects and
    // retries, then raises a memory error, told at the line the hook last saw).
    const std::size_t held = s.bytes_in_use + s.host_bytes + growth;
    if (held > s.limits.memory_bytes) {
      if (held > s.limits.memory_bytes + std::min<std::size_t>(s.limits.memory_bytes / 16, 8u << 20)) return nullptr;
      if (!s.over_cap) {
        s.over_cap = true;
        if (s.running != nullptr) lua_sethook(s.running, count_hook, LUA_MASKCOUNT, 1);
      }
    }
    // One VM instruction on a large string or table (a comparison, a next() over empty
    // slots) can take tens of milliseconds: from the first large block on, the hook runs
    // every ten instructions, so the deadline is seen within a few of them. lua_sethook
    // only sets fields, so it is safe here.
    if (new_size >= large_block && s.hook_every != large_every) {
      s.hook_every = large_every;
      if (s.running != nullptr) lua_sethook(s.running, count_hook, LUA_MASKCOUNT, large_every);
    }
    const std::uint64_t before = s.bytes_made;
    s.bytes_made += growth;
    if (s.work + s.bytes_made / bytes_per_unit > s.limits.instructions) {
      mark_stopped(s, Stop::work, s.last);
      return nullptr;
    }
    if ((before >> 24) != (s.bytes_made >> 24) && Clock::now() > s.deadline) {  // every 16 MiB made
      mark_stopped(s, Stop::time, s.last);
      return nullptr;
    }
  }
  void* block = std::realloc(ptr, new_size);
  if (block != nullptr) s.bytes_in_use = s.bytes_in_use - old_bytes + new_bytes;
  return block;
}

// After an allocation past the cap: the garbage collected, then either the script is
// under the cap again or it stops at this line.
void settle_memory(lua_State* L) {
  SandboxState& s = sandbox_of(L);
  s.over_cap = false;
  lua_gc(L, LUA_GCCOLLECT);
  if (s.bytes_in_use + s.host_bytes > s.limits.memory_bytes) stop(L, Stop::memory);
  lua_sethook(L, count_hook, LUA_MASKCOUNT, s.hook_every);
}

void count_hook(lua_State* L, lua_Debug* ar) {
  SandboxState& s = sandbox_of(L);
  if (lua_getinfo(L, "Sl", ar) != 0 && ar->currentline > 0) remember(s, ar->source, ar->currentline);
  if (s.over_cap && s.stop == Stop::none) settle_memory(L);
  charge(L, static_cast<std::uint64_t>(lua_gethookcount(L)));
}

// The first hook comes after one instruction, so a location is known from the start.
void first_hook(lua_State* L, lua_Debug* ar) {
  SandboxState& s = sandbox_of(L);
  if (lua_getinfo(L, "Sl", ar) != 0 && ar->currentline > 0) remember(s, ar->source, ar->currentline);
  lua_sethook(L, count_hook, LUA_MASKCOUNT, s.hook_every);
}

int print_to_stderr(lua_State* L) {
  SandboxState& s = sandbox_of(L);
  constexpr std::size_t max_print = 1u << 20;  // what a script may print in all
  constexpr std::size_t max_line = 64u << 10;
  const int n = lua_gettop(L);
  std::string line;
  for (int i = 1; i <= n; ++i) {
    std::size_t len = 0;
    const char* text = luaL_tolstring(L, i, &len);
    if (i > 1) line += '\t';
    line.append(text, std::min(len, max_line + 1 - std::min(line.size(), max_line)));
    lua_pop(L, 1);
    charge(L, len / bytes_per_unit + 1);
  }
  if (s.print_bytes >= max_print) return 0;
  line = printable(line, std::min(max_print - s.print_bytes, max_line));
  s.print_bytes += line.size() + 1;
  if (s.print_bytes >= max_print) line += "\n[print: the pattern printed more than 1 MiB; the rest is not shown]";
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fputc('\n', stderr);
  return 0;
}

// load(chunk [, chunkname [, mode [, env]]]) for strings of text only.
int load_text(lua_State* L) {
  std::size_t len = 0;
  const char* chunk = luaL_checklstring(L, 1, &len);
  const char* name = luaL_optstring(L, 2, "=(load)");
  const bool has_env = !lua_isnone(L, 4);
  charge(L, 4 * len + 100);  // compiling costs a few instructions' worth per byte
  const int status = luaL_loadbufferx(L, chunk, len, name, "t");
  if (status != LUA_OK) {
    raise_if_stopped(L, status);
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

bool has_location(const std::string& message) {
  const auto colon = message.find(':');
  if (colon == std::string::npos || colon == 0 || message.find('\n') < colon) return false;
  std::size_t i = colon + 1;
  while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i;
  return i > colon + 1 && i < message.size() && message[i] == ':';
}

// The pcall message handler, at the error with the stack still there: every message
// gets the script line it comes from, a non-string error object too.
int message_handler(lua_State* L) {
  if (sandbox_of(L).stop != Stop::none) return 1;  // a stop is told by run_chunk
  if (lua_type(L, 1) == LUA_TSTRING) {
    std::size_t len = 0;
    const char* text = lua_tolstring(L, 1, &len);
    const std::string message(text, len);
    if (has_location(message)) return 1;
    const std::string located = with_location(message, running_location(L));
    lua_pushlstring(L, located.data(), located.size());
    return 1;
  }
  const SourceLocation at = running_location(L);
  const std::string message = at.file + ":" + std::to_string(std::max(at.line, 1)) + ": error raised with a " +
                              luaL_typename(L, 1) + " value instead of a message; pass error() a string";
  lua_pushlstring(L, message.data(), message.size());
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
    if (lua_type(L, -2) == LUA_TSTRING && lua_type(L, -1) == LUA_TFUNCTION) {
      std::size_t len = 0;
      const char* key = lua_tolstring(L, -2, &len);
      if (len <= 64) names.emplace_back(key, len);
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  std::sort(names.begin(), names.end());  // ties go to the first name, whatever the table order
  std::string best;
  int best_distance = 3;
  for (const auto& n : names) {
    const int d = language::edit_distance(name, n);
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

void hook_thread(lua_State* co) {
  SandboxState& s = sandbox_of(co);
  const int every = s.stop != Stop::none ? 1 : s.hook_every;
  if (lua_gethook(co) != count_hook || lua_gethookcount(co) != every) lua_sethook(co, count_hook, LUA_MASKCOUNT, every);
}

Running::Running(lua_State* L, lua_State* co) : state_(sandbox_of(L)), before_(state_.running) {
  state_.running = co;
  hook_thread(co);
}

Running::~Running() {
  state_.running = before_;
  if (before_ != nullptr) hook_thread(before_);
}

SourceLocation running_location(lua_State* L) {
  SandboxState& s = sandbox_of(L);
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar) != 0; ++level) {
    if (lua_getinfo(L, "Sl", &ar) != 0 && ar.currentline > 0)
      return {ar.source[0] == '@' ? std::string(ar.source + 1) : s.file, ar.currentline};
  }
  return s.last.line > 0 ? s.last : SourceLocation{s.file, 1};
}

std::string with_location(const std::string& message, const SourceLocation& at) {
  if (has_location(message)) return message;
  return at.file + ":" + std::to_string(std::max(at.line, 1)) + ": " + message;
}

void charge(lua_State* L, std::uint64_t units) {
  SandboxState& s = sandbox_of(L);
  if (s.stop != Stop::none) raise_stop(L);
  s.work += units;
  if (s.work + s.bytes_made / bytes_per_unit > s.limits.instructions) stop(L, Stop::work);
  if (Clock::now() > s.deadline) stop(L, Stop::time);
}

void hold(lua_State* L, std::size_t bytes) {
  SandboxState& s = sandbox_of(L);
  s.host_bytes += bytes;
  if (s.bytes_in_use + s.host_bytes > s.limits.memory_bytes) stop(L, Stop::memory);
}

void stop(lua_State* L, Stop why, const std::string& detail) {
  mark_stopped(sandbox_of(L), why, running_location(L), detail);
  raise_stop(L);
}

void raise_if_stopped(lua_State* L, int status) {
  SandboxState& s = sandbox_of(L);
  if (s.stop == Stop::none && status == LUA_ERRMEM) mark_stopped(s, Stop::memory, s.last.line > 0 ? s.last : running_location(L));
  if (s.stop != Stop::none) raise_stop(L);
}

lua_State* open_sandbox(SandboxState& state) {
  state.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(state.limits.seconds));
  state.last = {state.file, 0};
  lua_State* L = lua_newstate(allocate, &state);
  if (L == nullptr) return nullptr;
  state.running = L;
  static const luaL_Reg libraries[] = {
      {LUA_GNAME, luaopen_base},       {LUA_TABLIBNAME, luaopen_table},
      {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},
      {LUA_UTF8LIBNAME, luaopen_utf8}, {LUA_COLIBNAME, luaopen_coroutine},
  };
  for (const luaL_Reg& lib : libraries) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  // Nothing that reaches files, bytecode, binary data or the collector's state.
  for (const char* name : {"dofile", "loadfile", "collectgarbage"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  lua_pushcfunction(L, load_text);
  lua_setglobal(L, "load");
  lua_pushcfunction(L, print_to_stderr);
  lua_setglobal(L, "print");
  lua_getglobal(L, LUA_STRLIBNAME);
  for (const char* name : {"dump", "pack", "unpack", "packsize"}) {
    lua_pushnil(L);
    lua_setfield(L, -2, name);
  }
  lua_pop(L, 1);
  open_budgeted_library(L);
  // math.random: the same numbers on every run.
  lua_getglobal(L, LUA_MATHLIBNAME);
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, state.seed);
  lua_call(L, 1, 0);
  lua_pop(L, 1);
  lua_sethook(L, first_hook, LUA_MASKCOUNT, 1);
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
  if (s.stop == Stop::none && status == LUA_ERRMEM) mark_stopped(s, Stop::memory, s.last);
  if (s.stop != Stop::none) throw PatternError(printable(s.stop_message));
  std::size_t len = 0;
  const char* text = lua_tolstring(L, -1, &len);
  const std::string message = text != nullptr ? std::string(text, len) : "error raised with a value that is not a message";
  throw PatternError(printable(with_location(message, s.last) + global_hint(L, message)));
}

}  // namespace knitc::runtime
