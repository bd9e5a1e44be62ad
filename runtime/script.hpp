// The state a running pattern script builds, and the helpers its bindings share.
// Internal to the runtime.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "language/chart.hpp"
#include "language/glossary.hpp"
#include "language/work.hpp"
#include "language/written.hpp"
#include "runtime.hpp"
#include "sandbox.hpp"

namespace knitc::runtime {

struct Script {
  RunOptions options;
  std::string directory;  // the pattern file's folder, for its lib/
  language::Work work;                // the pattern declared, its courses, the needle
  std::vector<std::string> yarn_ids;  // the pattern's yarns' ids, in order
  bool declared = false;
  int declared_line = 0;
  language::Legend legend = language::default_legend();
  std::vector<language::GlossaryEntry> glossary;  // stitch(...): the pattern's own abbreviations
  std::vector<std::string> warnings;
  std::size_t warnings_dropped = 0;   // warnings past max_warnings, counted only
  const char* running_verb = nullptr;  // the verb running now: verbs do not nest
  std::vector<std::string> modules;    // the module files require found, in order
};

inline constexpr std::size_t max_warnings = 200;  // kept; the rest are counted

Script& script_of(lua_State* L);

// Raises a Lua error "file:line: message" at the script line that called the binding
// (noting the pattern file's line too when that line is in a module).
[[noreturn]] void fail(lua_State* L, const std::string& message);
[[noreturn]] void fail_at(lua_State* L, const SourceLocation& at, const std::string& message);
// The script line that called the running binding, and its chunk.
SourceLocation caller_location(lua_State* L);
int caller_line(lua_State* L);
// The pattern file's own line that led here (a course worked by a library function is
// the designer's call), or `fallback` when no frame is in the pattern file.
SourceLocation pattern_location(lua_State* L, const SourceLocation& fallback);
std::string show(double v);

// The string at `index`, NUL bytes and all (lua_tostring would stop at the first).
std::string text_of(lua_State* L, int index);
// Adds a warning "file:line: warning: ..." (at most max_warnings are kept).
void warn(lua_State* L, const SourceLocation& at, const std::string& message);

std::optional<double> number_field(lua_State* L, int index, const std::string& table, const char* key);
std::optional<std::string> string_field(lua_State* L, int index, const std::string& table, const char* key);
// The keys of the table at index, sorted; all must be strings.
std::vector<std::string> sorted_keys(lua_State* L, int index, const std::string& table);
// Every key of the table at index is a field declared for `declared` (fields.cpp);
// `table` is how messages name it ("yarns.A").
void only_known_keys(lua_State* L, int index, const std::string& table, std::string_view declared);
// The same for a table that also holds a list: only its string keys are fields.
void only_known_fields(lua_State* L, int index, const std::string& table, std::string_view declared);
long long whole_number(lua_State* L, int arg, const std::string& what, long long lo, long long hi);
// The index of a declared yarn, or a located error naming the declared ones.
int yarn_index(lua_State* L, const std::string& id);

// pattern { ... }: name, gauge, yarns, knitting, seed.
int pattern_verb(lua_State* L);
// require "name": modules from the search folders.
int require_verb(lua_State* L);
// The yarn weight table of the reference docs.
std::string yarn_weight_markdown();
std::string yarn_fibre_markdown();
// The library's modules and functions, as each module declares them (working.declare),
// for the reference docs.
std::string library_markdown();
// Makes the registry table require caches modules in.
void open_modules(lua_State* L);
// The first line of the long string that starts at or after `line` in the chunk
// `source` (a chart's first row), or `line` if it cannot be found.
int long_string_first_line(const std::string& source, int line);
// The other verbs, declared in verbs.cpp. Each is registered through verb_entry,
// which refuses a verb called while another runs (from a metamethod of its arguments),
// charges the call, and turns a C++ allocation failure into the memory stop.
struct Verb {
  const char* name;
  lua_CFunction function;
  const char* usage;     // how it is called
  const char* summary;   // what it does
  const char* example;   // a line of Lua
};
std::span<const Verb> verb_table();
int verb_entry(lua_State* L);  // upvalue 1: the Verb, as a light userdata

// Limits of a fabric.
inline constexpr long long max_stitches = limits::stitches_on_needle;  // per course
inline constexpr long long max_loops = limits::script_loops;          // in the whole fabric
inline constexpr long long max_table_keys = 10'000;  // in a table a verb reads (pattern{}, a legend)

}  // namespace knitc::runtime
