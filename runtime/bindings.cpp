// The pattern verbs of the foundation: pattern{}, cast_on(n), rows(n, text), row(text).
// Each binding checks its arguments and raises errors located at the caller's line.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "sandbox.hpp"

namespace knitc::runtime {

namespace {

constexpr long long max_stitches = 100'000;   // per course
constexpr long long max_loops = 20'000'000;   // in the whole fabric

struct Script {
  Pattern pattern;
  bool declared = false;
  int declared_line = 0;
  int live = 0;            // live stitches on the needle
  int cast_on_line = 0;
  long long loops = 0;
};

Script& script_of(lua_State* L) { return *static_cast<Script*>(sandbox_of(L).user); }

// The line of the script that called the running binding.
int caller_line(lua_State* L) {
  lua_Debug ar;
  if (lua_getstack(L, 1, &ar) != 0 && lua_getinfo(L, "l", &ar) != 0) return ar.currentline;
  return 0;
}

[[noreturn]] void fail(lua_State* L, const std::string& message) {
  luaL_where(L, 1);
  lua_pushlstring(L, message.data(), message.size());
  lua_concat(L, 2);
  lua_error(L);
  std::abort();  // lua_error does not return
}

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A number field of the table at `index`, or nullopt if absent.
std::optional<double> number_field(lua_State* L, int index, const char* table, const char* key) {
  lua_getfield(L, index, key);
  std::optional<double> result;
  if (!lua_isnil(L, -1)) {
    if (!lua_isnumber(L, -1))
      fail(L, std::string(table) + "." + key + " must be a number, not a " + luaL_typename(L, -1));
    result = lua_tonumber(L, -1);
  }
  lua_pop(L, 1);
  return result;
}

std::optional<std::string> string_field(lua_State* L, int index, const char* table, const char* key) {
  lua_getfield(L, index, key);
  std::optional<std::string> result;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING)
      fail(L, std::string(table) + "." + key + " must be a string, not a " + luaL_typename(L, -1));
    result = lua_tostring(L, -1);
  }
  lua_pop(L, 1);
  return result;
}

// The string keys of the table at `index`, sorted: no table order leaks into messages.
std::vector<std::string> sorted_keys(lua_State* L, int index, const char* table) {
  std::vector<std::string> keys;
  index = lua_absindex(L, index);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING) fail(L, std::string(table) + " has a key that is not a name");
    keys.emplace_back(lua_tostring(L, -1));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

void only_known_keys(lua_State* L, int index, const char* table, std::initializer_list<const char*> known) {
  for (const std::string& key : sorted_keys(L, index, table)) {
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
      std::string list;
      for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
      fail(L, "unknown field '" + key + "' in " + table + "; known fields: " + list);
    }
  }
}

double in_range(lua_State* L, double v, const char* what, double lo, double hi, const char* unit) {
  if (std::isnan(v))
    fail(L, std::string(what) + " is NaN; it must be more than " + show(lo) + unit + " and at most " + show(hi) + unit);
  if (v <= lo || v > hi)
    fail(L, std::string(what) + " is " + show(v) + unit + "; it must be more than " + show(lo) + unit +
                " and at most " + show(hi) + unit);
  return v;
}

std::optional<std::string> normal_hex_color(const std::string& s) {
  const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  if (s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), hex)) {
    std::string out = s;
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
    return out;
  }
  if (s.size() == 4 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), hex)) {
    std::string out = "#";
    for (int i = 1; i < 4; ++i) out += std::string(2, static_cast<char>(std::tolower(s[i])));
    return out;
  }
  return std::nullopt;
}

void read_yarns(lua_State* L, int index, Pattern& p) {
  lua_getfield(L, index, "yarns");
  if (!lua_istable(L, -1))
    fail(L, "pattern{} needs yarns, e.g. yarns = { A = { diameter = 1.0, color = \"#d9c8a9\" } }");
  const int yarns = lua_gettop(L);
  for (const std::string& id : sorted_keys(L, yarns, "yarns")) {
    lua_getfield(L, yarns, id.c_str());
    if (!lua_istable(L, -1)) fail(L, "yarns." + id + " must be a table such as { diameter = 1.0, color = \"#d9c8a9\" }");
    const int t = lua_gettop(L);
    const std::string name = "yarns." + id;
    only_known_keys(L, t, name.c_str(), {"diameter", "color"});
    Yarn y;
    y.id = id;
    const auto d = number_field(L, t, name.c_str(), "diameter");
    if (!d) fail(L, name + " needs a diameter in mm, e.g. diameter = 1.0");
    y.diameter = in_range(L, *d, (name + ".diameter").c_str(), 0.0, 30.0, " mm");
    const std::string color = string_field(L, t, name.c_str(), "color").value_or("#d9c8a9");
    const auto hex = normal_hex_color(color);
    if (!hex) fail(L, name + ".color is \"" + color + "\"; give a CSS hex colour such as \"#d9c8a9\"");
    y.color = *hex;
    p.yarns.push_back(y);
    lua_pop(L, 1);
  }
  if (p.yarns.empty()) fail(L, "yarns is empty; declare one, e.g. yarns = { A = { diameter = 1.0 } }");
  lua_pop(L, 1);
}

void read_gauge(lua_State* L, int index, Pattern& p) {
  lua_getfield(L, index, "gauge");
  if (!lua_istable(L, -1))
    fail(L, "pattern{} needs a gauge, e.g. gauge = { stitches = 22, rows = 30 } (per 10 cm)");
  const int g = lua_gettop(L);
  only_known_keys(L, g, "gauge", {"stitches", "rows", "loop_width", "loop_height", "thickness"});
  const auto stitches = number_field(L, g, "gauge", "stitches");
  const auto rows = number_field(L, g, "gauge", "rows");
  const auto width = number_field(L, g, "gauge", "loop_width");
  const auto height = number_field(L, g, "gauge", "loop_height");
  const auto thickness = number_field(L, g, "gauge", "thickness");
  const bool per_10cm = stitches || rows, in_mm = width || height;
  if (per_10cm && in_mm)
    fail(L, "gauge mixes stitches/rows with loop_width/loop_height; give one pair or the other");
  if (per_10cm) {
    if (!stitches || !rows) fail(L, "gauge needs both stitches and rows (per 10 cm)");
    p.gauge.loop_width = 100.0 / in_range(L, *stitches, "gauge.stitches", 0.0, 200.0, " per 10 cm");
    const double spacing = 100.0 / in_range(L, *rows, "gauge.rows", 0.0, 300.0, " per 10 cm");
    p.gauge.loop_height = spacing / Gauge::course_spacing_ratio;
  } else if (in_mm) {
    if (!width || !height) fail(L, "gauge needs both loop_width and loop_height (mm)");
    p.gauge.loop_width = in_range(L, *width, "gauge.loop_width", 0.0, 100.0, " mm");
    p.gauge.loop_height = in_range(L, *height, "gauge.loop_height", 0.0, 100.0, " mm");
  } else {
    fail(L, "gauge is empty; give stitches and rows per 10 cm, or loop_width and loop_height in mm");
  }
  double thickest = 0.0;
  for (const Yarn& y : p.yarns) thickest = std::max(thickest, y.diameter);
  // Without a thickness the fabric is two yarns deep, as in the seed paper's examples.
  p.gauge.thickness = thickness ? in_range(L, *thickness, "gauge.thickness", 0.0, 100.0, " mm") : 2.0 * thickest;
  lua_pop(L, 1);
}

int pattern_verb(lua_State* L) {
  Script& s = script_of(L);
  if (s.declared)
    fail(L, "pattern{} was already given at line " + std::to_string(s.declared_line) + "; give it once");
  luaL_checktype(L, 1, LUA_TTABLE);
  only_known_keys(L, 1, "pattern{}", {"name", "gauge", "yarns", "knitting"});
  Pattern& p = s.pattern;
  p.name = string_field(L, 1, "pattern{}", "name").value_or("untitled");
  read_yarns(L, 1, p);  // before the gauge: its default thickness follows the yarn
  read_gauge(L, 1, p);
  const std::string knitting = string_field(L, 1, "pattern{}", "knitting").value_or("round");
  if (knitting == "flat") fail(L, "knitting = \"flat\" is not supported yet; knit in the round (the default)");
  if (knitting != "round") fail(L, "knitting is \"" + knitting + "\"; use \"round\" or \"flat\"");
  s.declared = true;
  s.declared_line = caller_line(L);
  return 0;
}

void need_pattern(lua_State* L, const char* verb) {
  if (!script_of(L).declared)
    fail(L, std::string(verb) + " comes before pattern{}; declare the pattern first");
}

long long whole_number(lua_State* L, int arg, const char* what, long long lo, long long hi) {
  if (lua_type(L, arg) != LUA_TNUMBER) fail(L, std::string(what) + " must be a whole number, not a " + luaL_typename(L, arg));
  int is_integer = 0;
  const long long v = lua_tointegerx(L, arg, &is_integer);  // 1e3 counts, 2.5 does not
  if (is_integer == 0) fail(L, std::string(what) + " must be a whole number, not " + show(lua_tonumber(L, arg)));
  if (v < lo || v > hi)
    fail(L, std::string(what) + " is " + std::to_string(v) + "; it must be from " + std::to_string(lo) + " to " +
                std::to_string(hi));
  return v;
}

int cast_on_verb(lua_State* L) {
  need_pattern(L, "cast_on");
  Script& s = script_of(L);
  if (s.cast_on_line != 0) fail(L, "cast_on was already called at line " + std::to_string(s.cast_on_line));
  s.live = static_cast<int>(whole_number(L, 1, "cast_on's stitch count", 1, max_stitches));
  s.pattern.cast_on = s.live;
  s.cast_on_line = caller_line(L);
  return 0;
}

// The foundation's row text: comma-separated stitches with optional counts ("k", "k2"),
// repeated across the row until the live stitches are used.
std::vector<Stitch> parse_row(lua_State* L, const std::string& text, int live) {
  std::vector<Stitch> unit;
  std::stringstream in(text);
  std::string token;
  while (std::getline(in, token, ',')) {
    const auto first = token.find_first_not_of(" \t");
    const auto last = token.find_last_not_of(" \t");
    if (first == std::string::npos) fail(L, "row \"" + text + "\" has an empty stitch between commas");
    token = token.substr(first, last - first + 1);
    std::size_t digits = token.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(token[digits - 1]))) --digits;
    const std::string name = token.substr(0, digits);
    const std::string count_text = token.substr(digits);
    if (name != "k")
      fail(L, "unknown stitch '" + name + "' in \"" + text + "\"; this version of knitc knows k (knit)");
    const long long count = count_text.empty() ? 1 : std::stoll(count_text.substr(0, 7));
    if (count < 1 || count > max_stitches) fail(L, "stitch count in '" + token + "' must be from 1 to 100000");
    unit.insert(unit.end(), static_cast<std::size_t>(count), Stitch::knit);
    if (static_cast<long long>(unit.size()) > max_stitches) fail(L, "row \"" + text + "\" is too long");
  }
  if (unit.empty()) fail(L, "row text is empty; give stitches such as \"k\"");
  const int n = static_cast<int>(unit.size());
  if (n > live || live % n != 0) {
    const int used = n > live ? n : live - live % n;
    const int left = live - used;
    fail(L, "row \"" + text + "\" uses " + std::to_string(n) + " stitches per repeat, which does not come out on " +
                std::to_string(live) + " live stitches (" +
                (left > 0 ? std::to_string(left) + " left over" : std::to_string(-left) + " missing") +
                "); change the repeat or the stitch count");
  }
  std::vector<Stitch> row;
  row.reserve(live);
  for (int i = 0; i < live / n; ++i) row.insert(row.end(), unit.begin(), unit.end());
  return row;
}

void add_courses(lua_State* L, long long count, const std::string& text) {
  Script& s = script_of(L);
  if (s.live == 0) fail(L, "no live stitches; call cast_on(n) first");
  const auto stitches = parse_row(L, text, s.live);
  if (s.loops + count * s.live > max_loops)
    fail(L, "the fabric would have more than " + std::to_string(max_loops) + " loops; knit a smaller piece");
  s.loops += count * s.live;
  Course c;
  c.stitches = stitches;
  c.yarn = 0;
  c.where = {sandbox_of(L).file, caller_line(L)};
  s.pattern.courses.insert(s.pattern.courses.end(), static_cast<std::size_t>(count), c);
}

int rows_verb(lua_State* L) {
  need_pattern(L, "rows");
  const long long count = whole_number(L, 1, "rows' count", 1, max_stitches);
  add_courses(L, count, luaL_checkstring(L, 2));
  return 0;
}

int row_verb(lua_State* L) {
  need_pattern(L, "row");
  add_courses(L, 1, luaL_checkstring(L, 1));
  return 0;
}

}  // namespace

Pattern run_pattern(std::string_view source, const std::string& file, const Limits& limits) {
  SandboxState state;
  state.limits = limits;
  state.file = file;
  Script script;
  state.user = &script;
  std::unique_ptr<lua_State, void (*)(lua_State*)> L(open_sandbox(state), lua_close);
  if (!L) throw PatternError(file + ": not enough memory to start the pattern's Lua state");
  static const luaL_Reg verbs[] = {
      {"pattern", pattern_verb}, {"cast_on", cast_on_verb}, {"rows", rows_verb}, {"row", row_verb}};
  for (const luaL_Reg& v : verbs) {
    lua_pushcfunction(L.get(), v.func);
    lua_setglobal(L.get(), v.name);
  }
  run_chunk(L.get(), source);

  if (!script.declared)
    throw PatternError(file + ":1: the script never calls pattern{}; start it with pattern { name = ..., gauge = ..., yarns = ... }");
  if (script.pattern.courses.empty()) {
    const int line = script.cast_on_line != 0 ? script.cast_on_line : script.declared_line;
    throw PatternError(file + ":" + std::to_string(line) + ": the pattern has no courses; add some, e.g. rows(10, \"k\")");
  }
  return std::move(script.pattern);
}

Pattern run_pattern_file(const std::string& path, const Limits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read pattern " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return run_pattern(text.str(), path, limits);
}

}  // namespace knitc::runtime
