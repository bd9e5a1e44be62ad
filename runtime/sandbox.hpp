// The sandboxed Lua state: only the safe standard libraries, text chunks only, and
// limits on instructions and memory. Internal to the runtime.
#pragma once

#include <map>
#include <string>

#include <lua.hpp>

#include "runtime.hpp"

namespace knitc::runtime {

// Everything the state's allocator and hooks need; lives as long as the state.
struct SandboxState {
  Limits limits;
  std::int64_t seed = 0;
  std::size_t bytes_in_use = 0;
  bool out_of_memory = false;
  std::uint64_t instructions = 0;
  std::string file;       // as messages name it
  std::map<std::string, std::string> sources;  // chunk name (no '@') -> text, for chart lines
  int last_line = 0;      // the line running when the count hook last fired
  void* user = nullptr;   // the bindings' own state
};

// A new state with base, string, table, math, utf8 and coroutine, minus dofile,
// loadfile, collectgarbage and string.dump; load accepts text only; print writes to
// stderr; math.random seeded with state.seed. Returns nullptr if even that does not fit in memory.
lua_State* open_sandbox(SandboxState& state);

// The SandboxState a sandboxed state was opened with.
SandboxState& sandbox_of(lua_State* L);

// Loads and runs `source` as chunk "@file". On failure throws PatternError with Lua's
// located message (or, for the limits, one of our own).
void run_chunk(lua_State* L, std::string_view source);

}  // namespace knitc::runtime
