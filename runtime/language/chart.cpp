#include "language/chart.hpp"

#include <algorithm>
#include <cctype>

namespace knitc::language {

bool Legend::set(const std::string& symbol, Worked worked) {
  if (symbol.empty() || std::any_of(symbol.begin(), symbol.end(), [](unsigned char c) { return std::isspace(c); }))
    return false;
  for (LegendEntry& e : entries) {
    if (e.symbol == symbol) {
      e.worked = worked;
      return true;
    }
  }
  entries.push_back({symbol, worked});
  // Longest first, then by text: matching is greedy and the order never depends on how
  // the script built its table.
  std::stable_sort(entries.begin(), entries.end(), [](const LegendEntry& a, const LegendEntry& b) {
    return a.symbol.size() != b.symbol.size() ? a.symbol.size() > b.symbol.size() : a.symbol < b.symbol;
  });
  return true;
}

const LegendEntry* Legend::match(std::string_view text) const {
  for (const LegendEntry& e : entries) {
    if (text.substr(0, e.symbol.size()) == e.symbol) return &e;
  }
  return nullptr;
}

Legend default_legend() {
  Legend legend;
  const auto table = stitch_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Worked w{static_cast<StitchId>(i), -1};
    legend.set(std::string(words(static_cast<StitchId>(i)).symbol), w);
    // Names work as symbols too, as written ("C4F", "p2tog"); names with spaces cannot.
    legend.set(std::string(table[i].name), w);
  }
  return legend;
}

namespace {

std::string describe(const Legend& legend) {
  std::string out;
  for (const auto& e : legend.entries) {
    if (e.symbol.size() == 1) out += (out.empty() ? "" : " ") + e.symbol;
  }
  return out;
}

// The legend symbol nearest to an unknown one: same letter in another case first.
std::string nearest_symbol(const Legend& legend, std::string_view unknown) {
  const LegendEntry* best = nullptr;
  int best_distance = 1 << 30;
  for (const auto& e : legend.entries) {
    const int d = edit_distance(unknown, e.symbol);
    if (d < best_distance) {
      best_distance = d;
      best = &e;
    }
  }
  if (best == nullptr) return "";
  return best->symbol + " (" + std::string(stitch(best->worked.stitch).name) + ")";
}

}  // namespace

std::variant<std::vector<ChartRow>, ChartError> parse_chart(std::string_view text, const Legend& legend) {
  std::vector<ChartRow> rows;
  int line = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view s = text.substr(start, end - start);
    ChartRow row;
    row.line = line;
    std::size_t i = 0;
    while (i < s.size()) {
      if (std::isspace(static_cast<unsigned char>(s[i]))) { ++i; continue; }
      const LegendEntry* e = legend.match(s.substr(i));
      if (e == nullptr) {
        std::size_t j = i + 1;
        while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j])) && legend.match(s.substr(j)) == nullptr) ++j;
        const std::string unknown(s.substr(i, j - i));
        return ChartError{line, "unknown chart symbol '" + unknown + "'; did you mean " + nearest_symbol(legend, unknown) +
                                    "? The legend has " + describe(legend) + " and stitch names such as C4F"};
      }
      row.cells.push_back(e->worked);
      i += e->symbol.size();
      const StitchDef& def = stitch(e->worked.stitch);
      if (std::max(def.consumes, def.produces) > 1) {
        while (i < s.size() && s[i] == '-') ++i;  // the drawn width of a cable
      }
    }
    if (!row.cells.empty()) rows.push_back(std::move(row));
    ++line;
    if (end == text.size()) break;
    start = end + 1;
  }
  std::reverse(rows.begin(), rows.end());
  return rows;
}

}  // namespace knitc::language
