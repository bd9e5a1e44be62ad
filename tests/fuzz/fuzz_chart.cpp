// libFuzzer target for charts: parse_chart with the default legend, and with one
// extended by multi-character symbols (some of them prefixes of names, or made of the
// '-' that draws a cable's width), checking what must hold whatever the text.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "language/chart.hpp"

namespace {

using namespace knitc;
using namespace knitc::language;

constexpr int extended_yarns = 3;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "fuzz_chart: invariant violated: %s\n", what);
  std::fflush(stderr);
  __builtin_trap();
}

void check(bool ok, const char* what) {
  if (!ok) violated(what);
}

const Legend& extended_legend() {
  static const Legend legend = [] {
    Legend l = default_legend();
    const auto set = [&l](const char* symbol, const char* name, int yarn) {
      check(l.set(symbol, Worked{stitch_id(name), yarn}), "Legend::set refused a symbol without whitespace");
    };
    set("kk", "k", 1);
    set("##", "C4F", -1);
    set("C4", "p", 2);      // a prefix of C4F and C4B: the longer name still wins
    set("//", "k2tog", 0);  // longer than '/'
    set("--", "no stitch", -1);
    set("Ab", "tuck", 1);
    set("T3", "C6B", -1);
    set("\xc3\xb6", "ssk", 2);  // UTF-8 o-umlaut
    check(!l.set("a b", Worked{stitch_id("k"), -1}), "Legend::set accepted a symbol with a space");
    check(!l.set("", Worked{stitch_id("k"), -1}), "Legend::set accepted an empty symbol");
    return l;
  }();
  return legend;
}

void run(std::string_view text, const Legend& legend, int yarns) {
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
  const auto parsed = parse_chart(text, legend);
  if (const auto* e = std::get_if<ChartError>(&parsed)) {
    check(!e->message.empty(), "parse_chart failed with an empty message");
    check(e->line >= 0 && e->line < lines, "a chart error's line is outside the text");
    return;
  }
  const std::vector<ChartRow>& rows = std::get<std::vector<ChartRow>>(parsed);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const ChartRow& row = rows[r];
    check(row.line >= 0 && row.line < lines, "a chart row's line is outside the text");
    if (r > 0) check(row.line < rows[r - 1].line, "chart rows are not bottom first");
    check(!row.cells.empty(), "an empty chart row was kept");
    check(row.cells.size() <= text.size(), "more cells than characters");
    for (const Worked& w : row.cells) {
      check(w.stitch < stitch_table().size(), "a chart cell has an invalid stitch id");
      check(w.yarn >= -1 && w.yarn < yarns, "a chart cell has a yarn out of range");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    static const Legend standard = default_legend();
    run(text, standard, 0);
    run(text, extended_legend(), extended_yarns);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_chart: exception escaped: %s\n", e.what());
    violated("an exception escaped");
  } catch (...) {
    violated("an unknown exception escaped");
  }
  return 0;
}
