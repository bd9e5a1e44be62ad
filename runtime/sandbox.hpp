// The sandboxed Lua state: only the safe standard libraries, text chunks only, and a
// budget of work, memory and time that the script cannot catch or outrun. Internal to
// the runtime; docs/security.md says what it promises and how each promise is kept.
//
// Work is counted in units of about one Lua VM instruction: the count hook adds the
// instructions run, the allocator adds one unit per 16 bytes a script makes, and every
// library function that loops without allocating (pattern matching, table.concat, ...)
// adds its steps before or while it takes them. Work and memory are deterministic: the
// same script stops at the same place on any machine. The deadline is a backstop for
// what the units misjudge, checked at every charge.
#pragma once

#include <chrono>
#include <map>
#include <string>

#include <lua.hpp>

#include "runtime.hpp"

namespace knitc::runtime {

// Why a script was stopped; the stop is final (every later charge or allocation fails).
enum class Stop { none, work, time, memory, string };

// Everything the state's allocator and hooks need; lives as long as the state.
struct SandboxState {
  Limits limits;
  std::int64_t seed = 0;
  std::size_t bytes_in_use = 0;   // held by the Lua state
  std::size_t host_bytes = 0;     // held by the bindings for the script (courses, texts)
  std::uint64_t bytes_made = 0;   // allocated over the whole run, charged as work
  std::uint64_t work = 0;         // units charged: instructions and library steps
  bool over_cap = false;          // an allocation went past the cap: the next hook settles it
  std::chrono::steady_clock::time_point deadline;
  Stop stop = Stop::none;
  std::string stop_message;       // "file:line: ..." once stopped
  std::string file;               // as messages name it
  std::map<std::string, std::string> sources;  // chunk name (no '@') -> text, for chart lines
  SourceLocation last;            // the script line last seen running
  const void* last_chunk = nullptr;  // the chunk name `last.file` was copied from
  std::size_t print_bytes = 0;    // written by print() so far
  lua_State* running = nullptr;   // the thread running now (the coroutine wrappers keep it)
  int hook_every = 1000;          // instructions between count hooks; 10 once a block is large
  void* user = nullptr;           // the bindings' own state
};

// A new state with base, string, table, math, utf8 and coroutine, minus dofile,
// loadfile, collectgarbage, string.dump and string.pack/unpack/packsize; load accepts
// text only; print writes to stderr; math.random seeded with state.seed; the library
// functions that catch errors, loop or allocate replaced by budgeted ones
// (sandbox_library.cpp). Returns nullptr if even that does not fit in memory.
lua_State* open_sandbox(SandboxState& state);

// The SandboxState a sandboxed state was opened with.
SandboxState& sandbox_of(lua_State* L);

// The innermost script line running in L (a Lua frame with a line), or the last one
// the hook saw when no frame has one.
SourceLocation running_location(lua_State* L);

// Adds `units` of work; stops the script once over its budget or past its deadline.
void charge(lua_State* L, std::uint64_t units);
// Counts `bytes` the bindings keep for the script (a course, a text) against the
// memory cap; stops the script if they do not fit. `release` gives them back.
void hold(lua_State* L, std::size_t bytes);
// Stops the script: records why, with the running line, and raises it. Every later
// charge, allocation and protected call raises it again, so the script cannot go on.
[[noreturn]] void stop(lua_State* L, Stop why, const std::string& detail = "");
// For the functions that catch errors (pcall, xpcall, coroutine.resume, load): if
// `status` is a failure that ends the script (a stop, or memory), raise it again.
void raise_if_stopped(lua_State* L, int status);

// Loads and runs `source` as chunk "@file". On failure throws PatternError with a
// located, printable message (Lua's, or for the limits, one of our own).
void run_chunk(lua_State* L, std::string_view source);

// Registers the budgeted replacements of the standard functions: base and coroutine
// (sandbox_library.cpp), table (sandbox_tables.cpp), string (sandbox_strings.cpp).
void open_budgeted_library(lua_State* L);
void open_budgeted_tables(lua_State* L);
void open_budgeted_strings(lua_State* L);

// Gives a thread the hook its state's threads have now (a resumed coroutine may have
// been made before the state turned to hooking every ten instructions).
void hook_thread(lua_State* co);

// While a coroutine runs: the state's running thread is `co`, then again the one before.
class Running {
 public:
  Running(lua_State* L, lua_State* co);
  ~Running();
  Running(const Running&) = delete;
  Running& operator=(const Running&) = delete;

 private:
  SandboxState& state_;
  lua_State* before_;
};

// A message with "file:line: " in front if it has none (Lua's "C stack overflow",
// "attempt to yield from outside a coroutine", "error in error handling" ...).
std::string with_location(const std::string& message, const SourceLocation& at);

}  // namespace knitc::runtime
