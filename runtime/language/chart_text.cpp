#include <algorithm>
#include <string>

#include "language/chart.hpp"

namespace knitc::language {

std::string chart_cell(StitchId id) {
  const StitchDef& s = stitch(id);
  std::string text(words(id).symbol);
  const int width = std::max(s.consumes, s.produces);
  if (s.family == StitchFamily::cable && width > 1) text.resize(std::max<std::size_t>(text.size(), 2 * width - 1), '-');
  return text;
}

std::string chart_text(const Pattern& pattern) {
  const std::size_t rows = pattern.courses.size();
  const std::size_t number_width = std::to_string(rows).size();
  // Yarn ids go beside the rows when any stitch is worked in another yarn than the cast-on's.
  const bool colours = std::any_of(pattern.courses.begin(), pattern.courses.end(), [&](const Course& c) {
    return std::any_of(c.ops.begin(), c.ops.end(), [&](const Op& op) { return op.yarn != pattern.cast_on_yarn; });
  });
  std::vector<std::string> lines;
  std::size_t widest = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    std::string cells;
    for (const Op& op : pattern.courses[r].ops) cells += (cells.empty() ? "" : " ") + chart_cell(op.stitch);
    widest = std::max(widest, cells.size());
    lines.push_back(std::move(cells));
  }
  std::string out = "# " + pattern.name + ": " + std::to_string(rows) + " rows on " + std::to_string(pattern.cast_on) +
                    " stitches, " + (pattern.knitting == Knitting::flat ? "flat" : "in the round") +
                    "; right side shown, row 1 at the bottom, each row numbered on the side it is read from\n";
  for (std::size_t r = rows; r-- > 0;) {
    const Course& c = pattern.courses[r];
    const std::string number = std::to_string(r + 1);
    const bool wrong = c.side == Side::wrong;
    std::string line = wrong ? std::string(number_width - number.size(), ' ') + number : std::string(number_width, ' ');
    line += "  " + lines[r];
    if (!wrong) line += std::string(widest - lines[r].size(), ' ') + "  " + number;
    if (colours) {
      if (wrong) line += std::string(widest - lines[r].size() + 2 + number_width, ' ');
      line += "   ";
      for (const Op& op : c.ops) line += (line.back() == ' ' ? "" : " ") + pattern.yarns[op.yarn].id;
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

}  // namespace knitc::language
