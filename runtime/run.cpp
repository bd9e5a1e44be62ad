// Running a pattern script: the sandbox, the verbs and stitch names as globals, the
// script, then the checks of the whole pattern.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>

#include "checks.hpp"
#include "script.hpp"
#include "source_files.hpp"

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

namespace {

// The script's warnings, printable, with a count of those not kept.
std::vector<std::string> warnings_of(const Script& script) {
  std::vector<std::string> out;
  for (const std::string& w : script.warnings) out.push_back(printable(w, 1000));
  if (script.warnings_dropped > 0)
    out.push_back("warning: " + std::to_string(script.warnings_dropped) + " more warnings not shown");
  return out;
}

RunResult run_script(std::string_view source, const std::string& file, const RunOptions& options, Script& script,
                     const std::function<void(lua_State*)>& inspect = {}) {
  if (source.size() > max_source_bytes)
    throw PatternError(file + ":1: the pattern is " + std::to_string(source.size() >> 10) + " KiB; knitc reads patterns of at most " +
                       std::to_string(max_source_bytes >> 20) + " MiB");
  SandboxState state;
  state.limits = options.limits;
  state.seed = options.seed.value_or(0);
  state.file = file;
  state.sources[file] = std::string(source);
  script.options = options;
  script.directory = std::filesystem::path(file).parent_path().string();
  state.user = &script;
  std::unique_ptr<lua_State, void (*)(lua_State*)> owner(open_sandbox(state), lua_close);
  lua_State* L = owner.get();
  if (L == nullptr) throw PatternError(file + ":1: not enough memory to start the pattern's Lua state");
  for (const Verb& v : verb_table()) {
    lua_pushlightuserdata(L, const_cast<Verb*>(&v));
    lua_pushcclosure(L, verb_entry, 1);
    lua_setglobal(L, v.name);
  }
  open_modules(L);
  const auto table = stitch_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string_view identifier = language::words(static_cast<StitchId>(i)).identifier;
    if (identifier.empty()) continue;
    lua_pushlstring(L, table[i].name.data(), table[i].name.size());
    lua_setglobal(L, std::string(identifier).c_str());
  }
  run_chunk(L, source);
  if (inspect) inspect(L);

  if (!script.declared)
    throw PatternError(file + ":1: the script never calls pattern{}; start it with pattern { name = ..., gauge = ..., yarns = ... }");
  Pattern p = script.work.take();
  if (p.courses.empty()) {
    const int line = script.work.cast_on_line() != 0 ? script.work.cast_on_line() : script.declared_line;
    throw PatternError(file + ":" + std::to_string(line) + ": the pattern has no courses; add some, e.g. rows(10, \"k\")");
  }
  RunResult result;
  for (const Diagnostic& d : check_pattern(p, {options.max_tucks, options.max_float_mm})) {
    const std::string where = d.where.file + ":" + std::to_string(d.where.line) + ": ";
    if (d.error) throw PatternError(where + d.message);
    result.warnings.push_back(printable(where + "warning: " + d.message, 1000));
  }
  const auto script_warnings = warnings_of(script);
  result.warnings.insert(result.warnings.end(), script_warnings.begin(), script_warnings.end());
  result.pattern = std::move(p);
  return result;
}

}  // namespace

RunResult run_pattern(std::string_view source, const std::string& file, const RunOptions& options) {
  Script script;
  auto files = [&] {
    std::vector<std::string> read{file};
    read.insert(read.end(), script.modules.begin(), script.modules.end());
    return read;
  };
  try {
    RunResult result = run_script(source, file, options, script);
    result.files = files();
    return result;
  } catch (const PatternError& e) {
    // The warnings given before the error are still news to the designer.
    throw PatternError(printable(e.what()), warnings_of(script), files());
  }
}

std::string library_markdown() {
  namespace fs = std::filesystem;
  std::vector<std::string> modules;
  for (const auto& entry : fs::directory_iterator(KNITC_LIBRARY_DIR)) {
    const std::string name = entry.path().stem().string();
    if (entry.path().extension() == ".lua" && name != "working") modules.push_back(name);
  }
  std::sort(modules.begin(), modules.end());
  std::string source = "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } } }\ncast_on(4)\n";
  for (const std::string& m : modules) source += "require \"" + m + "\"\n";
  source += "library_declared = require \"working\".declared\nrow \"k\"\n";
  std::string md;
  auto text = [](lua_State* L, int index, const char* key) {
    lua_getfield(L, index, key);
    std::string out = text_of(L, -1);
    lua_pop(L, 1);
    return out;
  };
  Script script;
  // Beside the library, so its own lib/ is the library (not a lib/ where knitc runs).
  const std::string file = (fs::path(KNITC_LIBRARY_DIR).parent_path() / "reference.lua").string();
  run_script(source, file, {}, script, [&](lua_State* L) {
    lua_getglobal(L, "library_declared");
    const int declared = lua_gettop(L);
    for (const std::string& m : modules) {
      lua_getfield(L, declared, m.c_str());
      if (!lua_istable(L, -1)) throw PatternError("patterns/lib/" + m + ".lua declares nothing (working.declare)");
      const int module = lua_gettop(L);
      md += "### " + m + "\n\n`local " + m + " = require \"" + m + "\"`: " + text(L, module, "summary") + ".\n\n";
      lua_getfield(L, module, "functions");
      const int functions = lua_gettop(L);
      for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(L, functions)); ++i) {
        lua_rawgeti(L, functions, i);
        const int function = lua_gettop(L);
        const std::string call = text(L, function, "call");
        md += "#### `" + call + "`\n\n" + text(L, function, "doc") + ".\n\n| " +
              (call.find('{') != std::string::npos ? "field" : "argument") + " | takes | default | |\n|---|---|---|---|\n";
        lua_getfield(L, function, "args");
        for (lua_Integer a = 1; a <= static_cast<lua_Integer>(lua_rawlen(L, -1)); ++a) {
          lua_rawgeti(L, -1, a);
          md += "|";
          for (int column = 1; column <= 4; ++column) {
            lua_rawgeti(L, -1, column);
            const std::string cell = text_of(L, -1);
            md += " " + (column == 1 ? "`" + cell + "`" : cell) + " |";
            lua_pop(L, 1);
          }
          md += "\n";
          lua_pop(L, 1);
        }
        lua_pop(L, 2);
        md += "\n";
      }
      lua_pop(L, 2);
    }
    lua_pop(L, 1);
  });
  return md;
}

RunResult run_pattern_file(const std::string& path, const RunOptions& options) {
  std::string text;
  try {
    text = read_source(path);
  } catch (const SourceTooLarge& e) {
    throw PatternError(printable(e.what()));
  }
  if (const std::string why = not_text(path, text); !why.empty()) throw PatternError(printable(why));
  return run_pattern(text, path, options);
}

}  // namespace knitc::runtime
