// Running a pattern script: the sandbox, the verbs and stitch names as globals, the
// script, then the checks of the whole pattern.
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "checks.hpp"
#include "script.hpp"

namespace knitc::runtime {

int long_string_first_line(const std::string& source, int line) {
  // Find the start of `line`, then the first long bracket [[ or [=*[ from there.
  std::size_t at = 0;
  for (int l = 1; l < line && at != std::string::npos; ++l) {
    at = source.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  if (at == std::string::npos) return line;
  int current = line;
  for (std::size_t i = at; i < source.size(); ++i) {
    if (source[i] == '\n') {
      ++current;
      continue;
    }
    if (source[i] != '[') continue;
    std::size_t j = i + 1;
    while (j < source.size() && source[j] == '=') ++j;
    if (j >= source.size() || source[j] != '[') continue;
    // Lua drops a newline right after the opening bracket.
    std::size_t k = j + 1;
    if (k < source.size() && source[k] == '\r') ++k;
    return k < source.size() && source[k] == '\n' ? current + 1 : current;
  }
  return line;
}

RunResult run_pattern(std::string_view source, const std::string& file, const RunOptions& options) {
  SandboxState state;
  state.limits = options.limits;
  state.seed = options.seed.value_or(0);
  state.file = file;
  state.sources[file] = std::string(source);
  Script script;
  script.options = options;
  script.directory = std::filesystem::path(file).parent_path().string();
  state.user = &script;
  std::unique_ptr<lua_State, void (*)(lua_State*)> owner(open_sandbox(state), lua_close);
  lua_State* L = owner.get();
  if (L == nullptr) throw PatternError(file + ": not enough memory to start the pattern's Lua state");
  lua_pushcfunction(L, pattern_verb);
  lua_setglobal(L, "pattern");
  for (const Verb& v : verb_table()) {
    lua_pushcfunction(L, v.function);
    lua_setglobal(L, v.name);
  }
  open_modules(L);
  for (const StitchDef& s : stitch_table()) {
    if (s.identifier.empty()) continue;
    lua_pushlstring(L, s.name.data(), s.name.size());
    lua_setglobal(L, std::string(s.identifier).c_str());
  }
  run_chunk(L, source);

  if (!script.declared)
    throw PatternError(file + ":1: the script never calls pattern{}; start it with pattern { name = ..., gauge = ..., yarns = ... }");
  Pattern& p = script.pattern;
  if (p.courses.empty()) {
    const int line = script.cast_on_line != 0 ? script.cast_on_line : script.declared_line;
    throw PatternError(file + ":" + std::to_string(line) + ": the pattern has no courses; add some, e.g. rows(10, \"k\")");
  }
  RunResult result;
  for (const Diagnostic& d : check_pattern(p, {options.max_tucks, options.max_float_mm})) {
    const std::string message = d.where.file + ":" + std::to_string(d.where.line) + ": " + d.message;
    if (d.error) throw PatternError(message);
    result.warnings.push_back("warning: " + message);
  }
  result.warnings.insert(result.warnings.end(), script.warnings.begin(), script.warnings.end());
  result.pattern = std::move(p);
  return result;
}

RunResult run_pattern_file(const std::string& path, const RunOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read pattern " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return run_pattern(text.str(), path, options);
}

}  // namespace knitc::runtime
