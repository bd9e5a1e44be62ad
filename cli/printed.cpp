#include "printed.hpp"
#include "sources.hpp"

#include <charconv>

#include "yarn/size.hpp"

namespace knitc::cli {

namespace {

// "22x30" or "22.5x31": stitches and rows per 10 cm, each above 0 and at most 200 and 300
// (the gauge fields' ranges).
std::optional<std::pair<double, double>> gauge_of(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  auto number = [](std::string_view s, double hi) -> std::optional<double> {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !(v > 0.0) || v > hi) return std::nullopt;
    return v;
  };
  const auto s = number(std::string_view(text).substr(0, x), 200.0);
  const auto r = number(std::string_view(text).substr(x + 1), 300.0);
  if (!s || !r) return std::nullopt;
  return std::pair{*s, *r};
}

}  // namespace

void add_printed_options(CLI::App* cmd, PrintedArgs& a) {
  cmd->add_option("--cast-on", a.options.cast_on,
                  "a printed pattern's cast-on (default: the count or multiple it states, else what row 1 fits)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--gauge", a.gauge, "a printed pattern's gauge, STITCHESxROWS per 10 cm (default 22x30)");
  cmd->add_option("--weight", a.options.weight, "a printed pattern's yarn weight (default dk; knitc reference lists them)");
  cmd->add_option("--selvedge", a.options.selvedge,
                  "a printed pattern's edge stitches: garter, chain or knit (default: chain if it says to slip the first "
                  "stitch of every row, else garter)")
      ->check(CLI::IsMember({"garter", "chain", "knit"}));
  cmd->add_option("--knitting", a.knitting, "a printed pattern's knitting, flat or round (default: round if its rows are rounds)")
      ->check(CLI::IsMember({"flat", "round"}));
}

std::optional<std::string> settle_printed_options(const CLI::App* cmd, const std::string& path, PrintedArgs& a) {
  if (!knitc::runtime::is_printed_pattern(path) || is_knitout(path)) {
    for (const char* name : {"--cast-on", "--gauge", "--weight", "--knitting", "--selvedge"})
      if (cmd->get_option(name)->count() != 0)
        return std::string("knitc: ") + name + " is for a printed pattern (a file that is not .lua); a script declares its own";
    return std::nullopt;
  }
  if (!a.gauge.empty()) {
    const auto g = gauge_of(a.gauge);
    if (!g) return "knitc: --gauge is \"" + a.gauge + "\"; give STITCHESxROWS per 10 cm, e.g. 22x30";
    a.options.stitches_per_10cm = g->first;
    a.options.rows_per_10cm = g->second;
  }
  std::string lower = a.options.weight;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (knitc::yarn::find_weight(lower) == nullptr)
    return "knitc: --weight is \"" + a.options.weight + "\"; knitc reference lists the weights (lace, fingering, sport, dk, worsted, aran, bulky, ...)";
  a.options.weight = lower;
  if (a.knitting == "flat") a.options.knitting = knitc::Knitting::flat;
  if (a.knitting == "round") a.options.knitting = knitc::Knitting::round;
  return std::nullopt;
}

}  // namespace knitc::cli
