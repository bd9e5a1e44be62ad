#include "fields.hpp"

#include <cassert>
#include <cstdio>
#include <optional>

#include "script.hpp"

namespace knitc::runtime {

namespace {

using K = FieldKind;

// Field{table, key, kind, lo, hi, unit, choices, fallback, value, has_value, default_doc, doc}
constexpr Field text(std::string_view table, std::string_view key, std::string_view fallback, std::string_view doc,
                     std::string_view default_doc = "") {
  return {table, key, K::text, 0, 0, "", "", fallback, 0, false, default_doc, doc};
}
constexpr Field choice(std::string_view table, std::string_view key, std::string_view choices, std::string_view fallback,
                       std::string_view doc) {
  return {table, key, K::choice, 0, 0, "", choices, fallback, 0, false, "", doc};
}
constexpr Field number(std::string_view table, std::string_view key, double lo, double hi, std::string_view unit,
                       std::string_view doc, std::optional<double> value = std::nullopt, std::string_view default_doc = "") {
  return {table, key, K::number, lo, hi, unit, "", "", value.value_or(0.0), value.has_value(), default_doc, doc};
}
constexpr Field amount(std::string_view table, std::string_view key, double hi, std::string_view unit, std::string_view doc,
                       std::optional<double> value = std::nullopt, std::string_view default_doc = "") {
  return {table, key, K::amount, 0, hi, unit, "", "", value.value_or(0.0), value.has_value(), default_doc, doc};
}
constexpr Field whole(std::string_view table, std::string_view key, double lo, double hi, std::string_view doc,
                      std::optional<double> value = std::nullopt, std::string_view default_doc = "") {
  return {table, key, K::whole, lo, hi, "", "", "", value.value_or(0.0), value.has_value(), default_doc, doc};
}
constexpr Field table(std::string_view table, std::string_view key, std::string_view doc, std::string_view default_doc = "") {
  return {table, key, K::table, 0, 0, "", "", "", 0, false, default_doc, doc};
}

constexpr Field fields[] = {
    text("pattern", "name", "untitled", "the pattern's name, for the files it makes"),
    table("pattern", "gauge", "the gauge: stitches and rows per 10 cm, or a loop's size in mm"),
    table("pattern", "yarns", "the yarns, each by a short name: { A = { ... }, B = { ... } }"),
    choice("pattern", "knitting", "round|flat", "round",
           "round: every row is worked from the right side; flat: even rows are wrong-side rows"),
    choice("pattern", "first_row", "right side|wrong side", "right side",
           "flat: the side row 1 is worked from, as a pattern printed \"Row 1 (WS)\" says; in the round always the right side"),
    choice("pattern", "selvedge", "garter|chain|knit", "garter",
           "how an edge stitch (edge st, selvedge st, sel st) is worked: garter, knitted at both ends of every row; "
           "chain, the first slipped knitwise and the last knitted; knit, knitted on right-side rows and purled on "
           "wrong-side ones"),
    whole("pattern", "seed", -9007199254740992.0, 9007199254740992.0, "math.random's seed (--seed overrides)", 0),

    number("gauge", "stitches", 0, 200, " per 10 cm", "stitches per 10 cm, with rows"),
    number("gauge", "rows", 0, 300, " per 10 cm", "rows per 10 cm, with stitches"),
    number("gauge", "loop_width", 0, 100, " mm", "a loop's width W in mm, with loop_height"),
    number("gauge", "loop_height", 0, 100, " mm", "a loop's height H in mm, with loop_width"),
    number("gauge", "thickness", 0, 100, " mm", "the fabric's thickness T", std::nullopt, "two yarn diameters"),

    number("yarn", "diameter", 0, 30, " mm", "the yarn's free diameter, as drawn (or give weight, wpi or tex)"),
    text("yarn", "weight", "", "a standard weight name (the table below): its diameters"),
    // wpi, tex and core_diameter bounded so that the free diameter stays within diameter's.
    number("yarn", "wpi", 1, 100, " wraps per inch", "wraps per inch, as knitters measure them: the diameters"),
    number("yarn", "tex", 0, 50000, " tex", "grams per kilometre: the core's diameter, from the fibre's density"),
    text("yarn", "fibre", "wool", "the fibre (the table below), whose density a tex yarn's core follows"),
    number("yarn", "core_diameter", 0, 15, " mm", "the compact core's diameter, less than the free diameter",
           std::nullopt, "the free diameter / 1.91"),
    number("yarn", "metres_per_100g", 1, 100000, " m per 100 g", "the yarn's length per 100 g, as its label gives it: the grams used",
           std::nullopt, "the weight's (the table below); tex's; else from the core and the fibre"),
    text("yarn", "color", "#d9c8a9", "a CSS hex colour, \"#rrggbb\" or \"#rgb\""),
    table("yarn", "colors",
          "a yarn dyed along its length (instead of color): runs of colour and their lengths in cm, repeated end to end, "
          "e.g. { {\"#b03030\", 40}, {\"#efe6d2\", 25} }",
          "one colour"),
    table("yarn", "heather",
          "a heathered yarn (instead of color): fibres of mixed colours, each with its share, e.g. "
          "{ {\"#6b7b8c\", 3}, {\"#d8d2c4\", 1} }",
          "one colour"),
    amount("yarn", "color_start", 100000, " cm", "colors: how far into the sequence the ball starts", 0),
    choice("yarn", "section", "circle|ellipse|plied", "circle",
           "circle; ellipse: a yarn pressed flat; plied: plies twisted about the centreline"),
    number("yarn", "aspect", 0.1, 1.0, "", "ellipse: minor / major", 0.7),
    whole("yarn", "plies", 2, 6, "plied: how many plies", 2),
    number("yarn", "twist", 0, 200, " turns per 10 cm", "plied: the plies' twist", 15),
    choice("yarn", "direction", "S|Z", "S", "plied: the twist's direction"),

    whole("yarn", "fibre_count", 1, 1000, "--section fibres: fibres drawn in each ply", std::nullopt, "the fibre's"),
    number("yarn", "fibre_diameter", 0, 0.5, " mm", "--section fibres and the baked textures: a fibre's diameter", std::nullopt, "the fibre's"),
    amount("yarn", "fibre_twist", 400, " turns per 10 cm", "--section fibres and the baked textures: the fibres' twist about their ply", std::nullopt,
           "the fibre's"),
    number("yarn", "fibre_packing", 0, 20, "", "--section fibres: how the fibres crowd the ply's middle (Zhao et al.'s beta)",
           std::nullopt, "the fibre's"),
    amount("yarn", "fibre_spread", 0.49, "", "--section fibres: the fibres' density at the ply's edge (Zhao et al.'s epsilon)",
           std::nullopt, "the fibre's"),
    amount("yarn", "migration", 1, "", "--section fibres (and the baked textures, where below 1): the innermost a fibre migrates, a fraction of its radius",
           std::nullopt, "the fibre's"),
    number("yarn", "migration_period", 0, 100, " turns", "--section fibres and the baked textures: turns about the ply per migration", std::nullopt,
           "the fibre's"),
    amount("yarn", "hairs", 500, " per cm", "--section fibres: hair flyaways (free fibre ends) per cm of yarn",
           std::nullopt, "the fibre's"),
    number("yarn", "hair_length", 0, 50, " mm", "--section fibres: the yarn's length a hair spans", std::nullopt, "the fibre's"),
    amount("yarn", "loops", 500, " per cm", "--section fibres: loop flyaways per cm of yarn", std::nullopt,
           "the fibre's"),
    amount("yarn", "halo", 20, " yarn radii", "--section fibres: how far flyaways reach beyond the yarn",
           std::nullopt, "the fibre's"),

    whole("course", "rep", 1, static_cast<double>(max_stitches), "the list worked this many times", std::nullopt, "fill the row"),
    text("course", "yarn", "", "a declared yarn to work the whole course in", "the current yarn"),

    table("chart", "legend", "symbols for this chart only, as legend{} takes them", "the legend so far"),
    whole("chart", "rep", 1, static_cast<double>(max_stitches), "the whole chart worked this many times upward", 1),
};

std::string default_text(const Field& f) {
  if (!f.default_doc.empty()) return std::string(f.default_doc);
  if (f.has_value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", f.value);
    return buf;
  }
  if (!f.fallback.empty()) return "\"" + std::string(f.fallback) + "\"";
  return "-";
}

std::string range_text(const Field& f) {
  char buf[96];
  switch (f.kind) {
    case K::number: std::snprintf(buf, sizeof buf, "number, more than %g, at most %g%s", f.lo, f.hi, std::string(f.unit).c_str()); return buf;
    case K::amount: std::snprintf(buf, sizeof buf, "number, 0 to %g%s", f.hi, std::string(f.unit).c_str()); return buf;
    case K::whole: std::snprintf(buf, sizeof buf, "whole number, %.0f to %.0f", f.lo, f.hi); return buf;
    case K::text: return "string";
    case K::table: return "table";
    case K::choice: {
      std::string out;
      std::string_view c = f.choices;
      for (std::size_t start = 0; start <= c.size();) {
        const std::size_t bar = std::min(c.find('|', start), c.size());
        out += (out.empty() ? "" : " or ") + ("\"" + std::string(c.substr(start, bar - start)) + "\"");
        start = bar + 1;
      }
      return out;
    }
  }
  return "";
}

}  // namespace

std::span<const Field> field_table() { return fields; }

const Field& field(std::string_view table, std::string_view key) {
  for (const Field& f : fields) {
    if (f.table == table && f.key == key) return f;
  }
  assert(false && "a field read but not declared in fields.cpp");
  return fields[0];
}

std::vector<std::string> field_keys(std::string_view table) {
  std::vector<std::string> keys;
  for (const Field& f : fields) {
    if (f.table == table) keys.emplace_back(f.key);
  }
  return keys;
}

std::string fields_markdown(std::string_view table) {
  std::string out = "| field | takes | default | |\n|---|---|---|---|\n";
  for (const Field& f : fields) {
    if (f.table != table) continue;
    out += "| `" + std::string(f.key) + "` | " + range_text(f) + " | " + default_text(f) + " | " + std::string(f.doc) + " |\n";
  }
  return out;
}

}  // namespace knitc::runtime
