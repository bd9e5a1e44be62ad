// A yarn dyed along its length: variegated, self-striping, or a gradient of solid runs.
// Its colours are runs of given lengths, repeated end to end as the dyer's sequence
// repeats. A knitter cannot predict by eye how the runs fall across a fabric (stripes,
// flashes, pooling): knitc knows every loop's yarn length, so it can show them.
// The rule for which run colours which millimetre of yarn lives here alone.
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace knitc::yarn {

struct ColourRun {
  std::string color;    // CSS hex, "#rrggbb"
  double length = 0.0;  // mm of yarn, > 0
  bool operator==(const ColourRun&) const = default;
};

// The most runs one yarn may have, and the longest run (mm): a dyer's sequence, not data.
inline constexpr std::size_t max_colour_runs = 256;
inline constexpr double max_run_length = 1'000'000.0;  // 1 km

// A heathered yarn: fibres of several colours blended in the spinning, each colour with its
// share of the fibres (> 0; the shares need not add to anything).
struct FibreColour {
  std::string color;  // CSS hex, "#rrggbb"
  double share = 0.0;
  bool operator==(const FibreColour&) const = default;
};
inline constexpr std::size_t max_fibre_colours = 64;

// The colour a fibre takes for a uniform number u in [0, 1): each colour for its share of u.
// `colours` is not empty and every share is > 0.
std::size_t fibre_colour_at(std::span<const FibreColour> colours, double u);

// The mm of yarn one repeat of `runs` takes.
double colour_repeat(std::span<const ColourRun> runs);

// The index of the run that colours the yarn `s` mm (>= 0) from where the knitter started,
// when the ball starts `start` mm (>= 0) into the sequence. `runs` is not empty and every
// length is > 0. A point exactly on a boundary takes the run that begins there.
std::size_t run_at(std::span<const ColourRun> runs, double start, double s);

}  // namespace knitc::yarn
