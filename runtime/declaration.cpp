// pattern { name = ..., gauge = ..., yarns = ..., knitting = ..., seed = ... }
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "fields.hpp"
#include "script.hpp"

namespace knitc::runtime {

namespace {

std::string weight_names() {
  std::string out;
  for (const yarn::Weight& w : yarn::weights()) {
    out += (out.empty() ? "" : ", ") + std::string(w.name);
    if (!w.aliases.empty()) {
      std::string a(w.aliases);
      std::replace(a.begin(), a.end(), '|', '/');
      out += " (" + a + ")";
    }
  }
  return out;
}

std::string fibre_names() {
  std::string out;
  for (const yarn::Fibre& f : yarn::fibres()) out += (out.empty() ? "" : ", ") + std::string(f.name);
  return out;
}

// A number field's value, in its declared range (fields.cpp).
double in_range(lua_State* L, double v, const std::string& what, const Field& f) {
  const std::string unit(f.unit);
  if (f.kind == FieldKind::amount) {
    // A whole bound in full ("100000", not "1e+05").
    const std::string hi = f.hi == std::floor(f.hi) ? std::to_string(static_cast<long long>(f.hi)) : show(f.hi);
    if (std::isnan(v) || v < 0.0 || v > f.hi)
      fail(L, what + " is " + (std::isnan(v) ? std::string("NaN") : show(v) + unit) + "; it must be 0 to " + hi + unit);
    return v;
  }
  if (std::isnan(v) || v <= f.lo || v > f.hi)
    fail(L, what + " is " + (std::isnan(v) ? std::string("NaN") : show(v) + unit) + "; it must be more than " +
                show(f.lo) + unit + " and at most " + show(f.hi) + unit);
  return v;
}

std::optional<std::string> normal_hex_color(const std::string& s) {
  const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  if ((s.size() != 7 && s.size() != 4) || s[0] != '#' || !std::all_of(s.begin() + 1, s.end(), hex)) return std::nullopt;
  std::string out = "#";
  for (std::size_t i = 1; i < s.size(); ++i) out += std::string(s.size() == 4 ? 2 : 1, static_cast<char>(std::tolower(s[i])));
  return out;
}

bool is_identifier(const std::string& s) {
  if (s.empty() || s.size() > 32 || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// A list of {colour, amount} pairs: colors' runs (cm) or heather's shares.
struct PairWords {
  const char* key;       // "colors"
  const char* pair;      // "{colour, cm}"
  const char* example;   // "e.g. colors = { ... }"
  const char* amount;    // "length"
  const char* number;    // "a number of cm, such as 40"
  const char* unit;      // " cm"
  const char* range;     // "a run of colour is more than 0 cm and at most "
  const char* items;     // "runs"
  double most;           // the largest amount
  std::size_t most_items;
};

std::vector<std::pair<std::string, double>> colour_pairs(lua_State* L, int t, const std::string& name, const PairWords& w) {
  std::vector<std::pair<std::string, double>> out;
  lua_getfield(L, t, w.key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return out;
  }
  const std::string key = name + "." + w.key;
  if (!lua_istable(L, -1)) fail(L, key + " must be a list of " + w.pair + " pairs, " + w.example);
  lua_getfield(L, t, "color");
  const bool has_color = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (has_color)
    fail(L, name + " gives both color and " + w.key + "; give color for one colour, " + w.key +
                (std::string(w.key) == "colors" ? " for a dyed sequence" : " for fibres of mixed colours"));
  const int list = lua_gettop(L);
  const auto n = static_cast<std::size_t>(lua_rawlen(L, list));
  if (n == 0) fail(L, key + " is empty; " + w.example);
  if (n > w.most_items)
    fail(L, key + " has " + std::to_string(n) + " " + w.items + "; knitc takes at most " + std::to_string(w.most_items));
  for (std::size_t i = 1; i <= n; ++i) {
    const std::string what = key + "[" + std::to_string(i) + "]";
    lua_rawgeti(L, list, static_cast<lua_Integer>(i));
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2) fail(L, what + " must be a pair " + w.pair + ", " + w.example);
    lua_rawgeti(L, -1, 1);
    lua_rawgeti(L, -2, 2);
    if (lua_type(L, -2) != LUA_TSTRING) fail(L, what + "'s colour must be a CSS hex string such as \"#b03030\"");
    const std::string color = text_of(L, -2);
    const auto hex = normal_hex_color(color);
    if (!hex) fail(L, what + "'s colour is \"" + printable(color, 40) + "\"; give a CSS hex colour such as \"#b03030\"");
    if (lua_type(L, -1) != LUA_TNUMBER) fail(L, what + "'s " + w.amount + " must be " + w.number);
    const double amount = lua_tonumber(L, -1);
    if (std::isnan(amount) || amount <= 0.0 || amount > w.most)
      fail(L, what + "'s " + w.amount + " is " + (std::isnan(amount) ? std::string("NaN") : show(amount) + w.unit) + "; " +
                  w.range + std::to_string(static_cast<long long>(w.most)) + w.unit);
    out.emplace_back(*hex, amount);
    lua_pop(L, 3);
  }
  lua_pop(L, 1);
  return out;
}

// colors = { {"#rrggbb", cm}, ... }, color_start = cm: a yarn dyed along its length.
// heather = { {"#rrggbb", share}, ... }: fibres of mixed colours.
void read_colours(lua_State* L, int t, const std::string& name, Yarn& y) {
  static constexpr PairWords runs{"colors", "{colour, cm}",
                                  "e.g. colors = { {\"#b03030\", 40}, {\"#efe6d2\", 25} } (cm of yarn each)", "length",
                                  "a number of cm, such as 40", " cm", "a run of colour is more than 0 cm and at most ", "runs",
                                  yarn::max_run_length / 10.0, yarn::max_colour_runs};
  static constexpr PairWords shares{"heather", "{colour, share}",
                                    "e.g. heather = { {\"#6b7b8c\", 3}, {\"#d8d2c4\", 1} } (each colour's share of the fibres)",
                                    "share", "a number, such as 3", "", "a share is more than 0 and at most ", "colours", 1e6,
                                    yarn::max_fibre_colours};
  for (const auto& [hex, cm] : colour_pairs(L, t, name, runs)) y.colours.push_back({hex, 10.0 * cm});
  for (const auto& [hex, share] : colour_pairs(L, t, name, shares)) y.heather.push_back({hex, share});
  if (!y.colours.empty() && !y.heather.empty())
    fail(L, name + " gives both colors and heather; knitc dyes a yarn along its length or blends its fibres, not both yet");
  const auto start = number_field(L, t, name, "color_start");
  if (start && y.colours.empty()) fail(L, name + ".color_start is for a yarn with colors");
  if (start) y.colour_start = 10.0 * in_range(L, *start, name + ".color_start", field("yarn", "color_start"));
  // The material's colour (and the knitout header's): the first run's or fibre colour's.
  if (!y.colours.empty()) y.color = y.colours.front().color;
  if (!y.heather.empty()) y.color = y.heather.front().color;
}

// The fibre's preset (yarn/fibres.hpp), each field overriding its part.
void read_fibres(lua_State* L, int t, const std::string& name, const std::string& fibre, Yarn& y) {
  y.fibres = yarn::fibre_preset(fibre);
  yarn::FibreModel& m = y.fibres;
  const auto number = [&](const char* key, double& into) {
    if (const auto v = number_field(L, t, name, key)) into = in_range(L, *v, name + "." + key, field("yarn", key));
  };
  lua_getfield(L, t, "fibre_count");
  if (!lua_isnil(L, -1)) {
    const Field& f = field("yarn", "fibre_count");
    m.fibres_per_ply = static_cast<int>(whole_number(L, lua_gettop(L), name + ".fibre_count", static_cast<long long>(f.lo),
                                                     static_cast<long long>(f.hi)));
  }
  lua_pop(L, 1);
  number("fibre_diameter", m.fibre_diameter);
  number("fibre_twist", m.fibre_twist);
  number("fibre_packing", m.packing);
  number("fibre_spread", m.spread);
  number("migration", m.migration);
  number("migration_period", m.migration_period);
  number("hairs", m.hairs);
  number("hair_length", m.hair_length);
  number("loops", m.loops);
  number("halo", m.halo);
  if (y.section == Section::plied) {  // the plies declared are the fibres' plies
    m.plies = y.plies;
    m.ply_twist = y.twist;
  }
}

// section = "circle" | "ellipse" (aspect) | "plied" (plies, twist, direction)
void read_section(lua_State* L, int t, const std::string& name, Yarn& y) {
  const std::string section = string_field(L, t, name, "section").value_or(std::string(field("yarn", "section").fallback));
  const auto aspect = number_field(L, t, name, "aspect");
  const auto twist = number_field(L, t, name, "twist");
  const auto direction = string_field(L, t, name, "direction");
  lua_getfield(L, t, "plies");
  const bool has_plies = !lua_isnil(L, -1);
  const Field& plies = field("yarn", "plies");
  if (has_plies)
    y.plies = static_cast<int>(whole_number(L, lua_gettop(L), name + ".plies", static_cast<long long>(plies.lo),
                                            static_cast<long long>(plies.hi)));
  lua_pop(L, 1);
  if (section == "circle") {
    y.section = Section::circle;
  } else if (section == "ellipse") {
    y.section = Section::ellipse;
    y.aspect = aspect ? in_range(L, *aspect, name + ".aspect", field("yarn", "aspect")) : field("yarn", "aspect").value;
  } else if (section == "plied") {
    y.section = Section::plied;
    if (!has_plies) y.plies = static_cast<int>(plies.value);
    y.twist = twist ? in_range(L, *twist, name + ".twist", field("yarn", "twist")) : field("yarn", "twist").value;
    const std::string d = direction.value_or(std::string(field("yarn", "direction").fallback));
    if (d != "S" && d != "Z" && d != "s" && d != "z") fail(L, name + ".direction is \"" + d + "\"; give \"S\" or \"Z\"");
    y.z_twist = d == "Z" || d == "z";
  } else {
    fail(L, name + ".section is \"" + section + "\"; give \"circle\", \"ellipse\" or \"plied\"");
  }
  if (aspect && y.section != Section::ellipse) fail(L, name + ".aspect is for section = \"ellipse\"");
  if ((has_plies || twist || direction) && y.section != Section::plied)
    fail(L, name + ".plies, twist and direction are for section = \"plied\"");
}

// The yarn's two diameters (compiler/yarn/size.hpp) from one of diameter, weight, wpi and
// tex, and a core_diameter when the designer knows it.
void read_size(lua_State* L, int t, const std::string& name, Yarn& y) {
  const auto diameter = number_field(L, t, name, "diameter");
  const auto weight = string_field(L, t, name, "weight");
  const auto wpi = number_field(L, t, name, "wpi");
  const auto tex = number_field(L, t, name, "tex");
  const auto core = number_field(L, t, name, "core_diameter");
  const auto fibre_name = string_field(L, t, name, "fibre");
  std::vector<std::string> given;
  if (diameter) given.emplace_back("diameter");
  if (weight) given.emplace_back("weight");
  if (wpi) given.emplace_back("wpi");
  if (tex) given.emplace_back("tex");
  if (given.size() > 1) {
    std::string both;
    for (std::size_t i = 0; i < given.size(); ++i) both += (i == 0 ? "" : i + 1 == given.size() ? " and " : ", ") + given[i];
    fail(L, name + " gives " + (given.size() == 2 ? "both " : "") + both + "; give one");
  }
  const yarn::Fibre* fibre = yarn::find_fibre(language::lower(fibre_name.value_or(std::string(yarn::default_fibre))));
  if (fibre == nullptr) fail(L, name + ".fibre is \"" + *fibre_name + "\"; known fibres: " + fibre_names());
  yarn::Size size;
  if (weight) {
    const yarn::Weight* w = yarn::find_weight(language::lower(*weight));
    if (w == nullptr) fail(L, name + ".weight is \"" + *weight + "\"; known weights: " + weight_names());
    size = yarn::from_wpi(w->wpi);
  } else if (wpi) {
    size = yarn::from_wpi(in_range(L, *wpi, name + ".wpi", field("yarn", "wpi")));
  } else if (tex) {
    size = yarn::from_tex(in_range(L, *tex, name + ".tex", field("yarn", "tex")), fibre->density);
  } else if (diameter) {
    size = yarn::from_free_diameter(in_range(L, *diameter, name + ".diameter", field("yarn", "diameter")));
  } else if (core) {
    size = yarn::from_core_diameter(in_range(L, *core, name + ".core_diameter", field("yarn", "core_diameter")));
  } else {
    fail(L, name + " needs a size: a diameter in mm, a weight, wpi or tex, e.g. diameter = 1.0 or weight = \"dk\"");
  }
  if (core) {
    size.core_diameter = in_range(L, *core, name + ".core_diameter", field("yarn", "core_diameter"));
    if (size.core_diameter >= size.free_diameter)
      fail(L, name + ".core_diameter is " + show(size.core_diameter) + " mm, not less than the free diameter " +
                  show(size.free_diameter) + " mm; the core is the compact middle of the yarn");
  }
  y.diameter = size.free_diameter;
  y.core_diameter = size.core_diameter;
  // Its weight per length: the label's, else the weight's typical, else tex's, else the
  // core's fibre at its packing.
  const auto metres = number_field(L, t, name, "metres_per_100g");
  if (metres) y.grams_per_metre = 100.0 / in_range(L, *metres, name + ".metres_per_100g", field("yarn", "metres_per_100g"));
  else if (weight) y.grams_per_metre = 100.0 / yarn::find_weight(language::lower(*weight))->metres_per_100g;
  else if (tex) y.grams_per_metre = *tex / 1000.0;
  else y.grams_per_metre = yarn::grams_per_metre(y.core_diameter, fibre->density);
}

void read_yarns(lua_State* L, int index, Pattern& p) {
  lua_getfield(L, index, "yarns");
  if (!lua_istable(L, -1))
    fail(L, "pattern{} needs yarns, e.g. yarns = { A = { diameter = 1.0, color = \"#d9c8a9\" } }");
  const int yarns = lua_gettop(L);
  for (const std::string& id : sorted_keys(L, yarns, "yarns")) {
    if (!is_identifier(id)) fail(L, "yarn name '" + id + "' must be a short name of letters, digits and _, such as A or MC");
    if (language::find_stitch(id)) fail(L, "yarn name '" + id + "' is also a stitch; name it otherwise, e.g. " + id + "1");
    lua_getfield(L, yarns, id.c_str());
    if (!lua_istable(L, -1)) fail(L, "yarns." + id + " must be a table such as { diameter = 1.0, color = \"#d9c8a9\" }");
    const int t = lua_gettop(L);
    const std::string name = "yarns." + id;
    only_known_keys(L, t, name, "yarn");
    Yarn y;
    y.id = id;
    read_size(L, t, name, y);
    const std::string color = string_field(L, t, name, "color").value_or(std::string(field("yarn", "color").fallback));
    const auto hex = normal_hex_color(color);
    if (!hex) fail(L, name + ".color is \"" + color + "\"; give a CSS hex colour such as \"#d9c8a9\"");
    y.color = *hex;
    read_colours(L, t, name, y);
    read_section(L, t, name, y);
    read_fibres(L, t, name, language::lower(string_field(L, t, name, "fibre").value_or(std::string(yarn::default_fibre))), y);
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
  only_known_keys(L, g, "gauge", "gauge");
  const auto stitches = number_field(L, g, "gauge", "stitches");
  const auto rows = number_field(L, g, "gauge", "rows");
  const auto width = number_field(L, g, "gauge", "loop_width");
  const auto height = number_field(L, g, "gauge", "loop_height");
  const auto thickness = number_field(L, g, "gauge", "thickness");
  const bool per_10cm = stitches || rows, in_mm = width || height;
  if (per_10cm && in_mm) fail(L, "gauge mixes stitches/rows with loop_width/loop_height; give one pair or the other");
  if (per_10cm) {
    if (!stitches || !rows) fail(L, "gauge needs both stitches and rows (per 10 cm)");
    p.gauge.loop_width = 100.0 / in_range(L, *stitches, "gauge.stitches", field("gauge", "stitches"));
    const double spacing = 100.0 / in_range(L, *rows, "gauge.rows", field("gauge", "rows"));
    p.gauge.loop_height = spacing / Gauge::course_spacing_ratio;
  } else if (in_mm) {
    if (!width || !height) fail(L, "gauge needs both loop_width and loop_height (mm)");
    p.gauge.loop_width = in_range(L, *width, "gauge.loop_width", field("gauge", "loop_width"));
    p.gauge.loop_height = in_range(L, *height, "gauge.loop_height", field("gauge", "loop_height"));
  } else {
    fail(L, "gauge is empty; give stitches and rows per 10 cm, or loop_width and loop_height in mm");
  }
  double thickest = 0.0;
  std::string thickest_id;
  for (const Yarn& y : p.yarns) {
    if (y.diameter > thickest) thickest = y.diameter, thickest_id = y.id;
  }
  // Without a thickness the fabric is two yarns deep, as in the seed paper's examples.
  p.gauge.thickness = thickness ? in_range(L, *thickness, "gauge.thickness", field("gauge", "thickness")) : 2.0 * thickest;
  // A loop's width holds its two legs side by side: a yarn over half of it cannot fit.
  const double W = p.gauge.loop_width;
  if (thickest > 0.5 * W)
    fail(L, "yarn " + thickest_id + " is " + show(thickest) + " mm thick but a loop is only " + show(W) +
                " mm wide; a loop holds a yarn of at most " + show(0.5 * W) + " mm: use a thinner yarn or fewer stitches per 10 cm");
  if (p.gauge.thickness < thickest)
    fail(L, "gauge.thickness is " + show(p.gauge.thickness) + " mm, thinner than yarn " + thickest_id + " (" + show(thickest) +
                " mm); the fabric is at least one yarn thick");
  lua_pop(L, 1);
}

}  // namespace

std::string yarn_weight_markdown() {
  std::string out =
      "| weight | also | wraps per inch | free diameter (mm) | core diameter (mm) | m per 100 g |\n|---|---|---|---|---|---|\n";
  for (const yarn::Weight& w : yarn::weights()) {
    std::string a(w.aliases);
    std::replace(a.begin(), a.end(), '|', ',');
    const yarn::Size size = yarn::from_wpi(w.wpi);
    char d[64];
    std::snprintf(d, sizeof d, "%.2f | %.2f", size.free_diameter, size.core_diameter);
    out += "| " + std::string(w.name) + " | " + a + " | " + show(w.wpi) + " | " + d + " | " + show(w.metres_per_100g) + " |\n";
  }
  return out;
}

std::string yarn_fibre_markdown() {
  std::string out = "| fibre | density (g/cm³) |\n|---|---|\n";
  for (const yarn::Fibre& f : yarn::fibres()) out += "| " + std::string(f.name) + " | " + show(f.density) + " |\n";
  return out;
}

int pattern_verb(lua_State* L) {
  Script& s = script_of(L);
  if (s.declared)
    fail(L, "pattern{} was already given at line " + std::to_string(s.declared_line) + "; give it once");
  if (lua_type(L, 1) != LUA_TTABLE)
    fail(L, std::string("pattern takes a table: pattern { name = ..., gauge = ..., yarns = ... }, not a ") + luaL_typename(L, 1));
  only_known_keys(L, 1, "pattern{}", "pattern");
  // Read whole before anything is kept: a pattern{} that fails half-way (and is caught
  // by pcall) leaves no yarns behind.
  Pattern p;
  p.name = string_field(L, 1, "pattern{}", "name").value_or(std::string(field("pattern", "name").fallback));
  read_yarns(L, 1, p);  // before the gauge: its default thickness follows the yarn
  read_gauge(L, 1, p);
  const std::string knitting = string_field(L, 1, "pattern{}", "knitting").value_or(std::string(field("pattern", "knitting").fallback));
  if (knitting == "flat") p.knitting = Knitting::flat;
  else if (knitting != "round") fail(L, "knitting is \"" + printable(knitting, 100) + "\"; use \"round\" or \"flat\"");
  const std::string selvedge = string_field(L, 1, "pattern{}", "selvedge").value_or(std::string(field("pattern", "selvedge").fallback));
  if (selvedge != "garter" && selvedge != "chain" && selvedge != "knit")
    fail(L, "selvedge is \"" + printable(selvedge, 100) + "\"; use \"garter\", \"chain\" or \"knit\"");
  lua_getfield(L, 1, "seed");
  if (!lua_isnil(L, -1)) {
    const Field& f = field("pattern", "seed");
    const long long seed =
        whole_number(L, lua_gettop(L), "pattern{}.seed", static_cast<long long>(f.lo), static_cast<long long>(f.hi));
    if (!s.options.seed) {  // --seed wins over the script's
      lua_getglobal(L, "math");
      lua_getfield(L, -1, "randomseed");
      lua_pushinteger(L, seed);
      lua_call(L, 1, 0);
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  for (const Yarn& y : p.yarns) s.yarn_ids.push_back(y.id);
  s.work = language::Work(std::move(p), {max_stitches, max_loops});
  const std::string first_row = string_field(L, 1, "pattern{}", "first_row").value_or(std::string(field("pattern", "first_row").fallback));
  if (first_row != "right side" && first_row != "wrong side")
    fail(L, "first_row is \"" + printable(first_row, 100) + "\"; use \"right side\" or \"wrong side\"");
  if (first_row == "wrong side") {
    if (s.work.pattern().knitting != Knitting::flat)
      fail(L, "first_row is \"wrong side\" but the pattern is knitted in the round, where every row is worked from the right side");
    s.work.start_on_wrong_side();
  }
  s.work.set_selvedge(selvedge == "chain" ? language::Selvedge::chain
                      : selvedge == "knit" ? language::Selvedge::knit
                                           : language::Selvedge::garter);
  s.declared = true;
  s.declared_line = caller_line(L);
  return 0;
}

}  // namespace knitc::runtime
