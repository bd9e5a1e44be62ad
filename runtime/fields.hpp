// The fields of the verbs' tables, declared once as data: pattern{}, its gauge and each
// yarn, course{} and chart{}. The bindings check names, kinds and ranges against this
// table, and `knitc reference` prints it (docs/language.md). Rules that join fields
// (diameter or weight, stitches with rows) stay in the bindings that read them.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace knitc::runtime {

enum class FieldKind { number, amount, whole, text, choice, table };

struct Field {
  std::string_view table;     // "pattern", "gauge", "yarn", "course", "chart"
  std::string_view key;
  FieldKind kind;
  double lo = 0.0, hi = 0.0;  // number: lo < v <= hi; amount (lo 0) and whole: lo <= v <= hi
  std::string_view unit;      // " mm", " per 10 cm", ...
  std::string_view choices;   // choice: the values, '|' between
  std::string_view fallback;  // text and choice: the default value; empty: none
  double value = 0.0;         // number and whole: the default value, when `has_value`
  bool has_value = false;
  std::string_view default_doc;  // a default that is no single value ("two yarn diameters")
  std::string_view doc;       // one line
};

std::span<const Field> field_table();
// The field `key` of `table`; asserts it is declared.
const Field& field(std::string_view table, std::string_view key);
// The keys declared for `table`, in order (for "unknown field ... known fields: ...").
std::vector<std::string> field_keys(std::string_view table);
// The reference docs of a table's fields: a Markdown table.
std::string fields_markdown(std::string_view table);

}  // namespace knitc::runtime
