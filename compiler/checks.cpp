#include "checks.hpp"

#include <cmath>
#include <cstdio>

namespace knitc {

namespace {

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

// Floats in one course: runs of slipped stitches, and for each yarn of a stranded course
// the stitches between two of its own.
void check_floats(const Pattern& p, std::size_t row, const CheckLimits& limits, std::vector<Diagnostic>& out) {
  const Course& c = p.courses[row];
  const double W = p.gauge.loop_width;
  const int limit = static_cast<int>(std::floor(limits.max_float_mm / W));
  int run = 0, longest = 0;
  for (const Op& op : c.ops) {
    run = stitch(op.stitch).family == StitchFamily::slip && !stitch(op.stitch).unreached ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  if (longest > limit) {
    out.push_back({c.where,
                   "row " + std::to_string(row + 1) + " slips " + std::to_string(longest) + " stitches in a row: a float of " +
                       mm(longest * W) + " mm, over the " + mm(limits.max_float_mm) + " mm that wears well; break the run of slips",
                   false});
  }
  std::vector<int> last(p.yarns.size(), -1), gap(p.yarns.size(), 0);
  int position = 0;
  for (const Op& op : c.ops) {
    if (stitch(op.stitch).produces == 0) continue;
    if (last[op.yarn] >= 0) gap[op.yarn] = std::max(gap[op.yarn], position - last[op.yarn] - 1);
    last[op.yarn] = position++;
  }
  for (std::size_t y = 0; y < p.yarns.size(); ++y) {
    if (gap[y] > limit) {
      out.push_back({c.where,
                     "row " + std::to_string(row + 1) + " carries yarn " + p.yarns[y].id + " across " + std::to_string(gap[y]) +
                         " stitches: a float of " + mm(gap[y] * W) + " mm, over the " + mm(limits.max_float_mm) +
                         " mm that wears well; catch the float or use the yarn more often",
                     false});
    }
  }
}

}  // namespace

std::vector<Diagnostic> check_pattern(const Pattern& p, const CheckLimits& limits) {
  std::vector<Diagnostic> out;
  // Tucks held on each live stitch: a tuck adds to the loops its needle holds, anything
  // else knits them off.
  std::vector<int> held(static_cast<std::size_t>(p.cast_on), 0);
  for (std::size_t row = 0; row < p.courses.size(); ++row) {
    const Course& c = p.courses[row];
    std::vector<int> next;
    next.reserve(held.size());
    std::size_t at = 0;
    bool reported = false;
    for (const Op& op : c.ops) {
      const StitchDef& s = stitch(op.stitch);
      if (s.family == StitchFamily::tuck) {
        for (int k = 0; k < s.consumes; ++k) {
          const int stack = (at < held.size() ? held[at] : 0) + 1;
          if (stack > limits.max_tucks && !reported) {
            out.push_back({c.where,
                           "row " + std::to_string(row + 1) + " stacks " + std::to_string(stack) + " tucks on stitch " +
                               std::to_string(next.size() + 1) + "; a needle holds at most " + std::to_string(limits.max_tucks) +
                               " before they cannot be knitted off: knit the stitch in between",
                           true});
            reported = true;
          }
          next.push_back(stack);
          ++at;
        }
        continue;
      }
      at += static_cast<std::size_t>(s.consumes);
      next.insert(next.end(), static_cast<std::size_t>(s.produces), 0);
    }
    held = std::move(next);
    check_floats(p, row, limits, out);
  }
  return out;
}

}  // namespace knitc
