#include "yarn/colour.hpp"

#include <cassert>
#include <cmath>

namespace knitc::yarn {

double colour_repeat(std::span<const ColourRun> runs) {
  double total = 0.0;
  for (const ColourRun& r : runs) total += r.length;
  return total;
}

std::size_t run_at(std::span<const ColourRun> runs, double start, double s) {
  assert(!runs.empty() && start >= 0.0 && s >= 0.0);
  const double repeat = colour_repeat(runs);
  assert(repeat > 0.0);
  double at = std::fmod(start + s, repeat);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (at < runs[i].length) return i;
    at -= runs[i].length;
  }
  return runs.size() - 1;  // rounding past the last boundary
}

std::size_t fibre_colour_at(std::span<const FibreColour> colours, double u) {
  assert(!colours.empty());
  double total = 0.0;
  for (const FibreColour& c : colours) total += c.share;
  double at = u * total;
  for (std::size_t i = 0; i < colours.size(); ++i) {
    if (at < colours[i].share) return i;
    at -= colours[i].share;
  }
  return colours.size() - 1;
}

}  // namespace knitc::yarn
