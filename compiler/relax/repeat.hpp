// A fabric relaxed by its repeat (issue 16): the smallest block of loops that repeats
// across a flat fabric's interior is found from the layout, relaxed alone as one tile of
// an endless fabric (Boundary::periodic), tiled across the fabric, and then the edges
// (cast-on, bind-off, selvedges) and whatever does not repeat are relaxed against the
// tiled interior, which is held. Internal to relax/.
#pragma once

#include <optional>

#include "relax/chains.hpp"
#include "relax/relax.hpp"

namespace knitc::relax {

// A block of `wales` x `courses` loops whose first loop is at (course0, wale0): every loop
// of the fabric's interior is laid out as the one a whole number of blocks away, the same
// stitch, shape, yarn and working direction, its data points the same shape, and the
// blocks a whole number of loop widths and course spacings apart.
struct Repeat {
  int wales = 0, courses = 0;
  int wale0 = 0, course0 = 0;
  int wale_period = 0, course_period = 0;  // the smallest repeat, of which the block is whole times
};

// The tile's least size, in wales and courses: a repeat smaller than this is taken as many
// times as it needs. The periodic contacts wrap one repeat each way, so a tile of two
// courses reaches the loops two courses up and down, past any a loop touches. Four wales,
// because a tile settles by its points' mean move, which a narrower tile's creeping width
// makes smaller: a 1x1 rib's tile of 2 wales stops at 2.9 mm a wale where one of 4 draws
// in on (docs/relaxation.md).
inline constexpr int least_tile_wales = 4;
inline constexpr int least_tile_courses = 2;
// Courses at most this many at either end of the interior that do not repeat are left out
// of it (relaxed with the edges): a machine program's cast-on and bind-off take a few.
inline constexpr int most_trimmed = 4;
// Where no period repeats across the whole interior, one that all but this share of its
// loops repeat in is taken, the rest relaxed with the edges (docs/relaxation.md).
inline constexpr double most_not_repeating = 0.1;
// Loops at most this many loops (across or up) from one that is not tiled stay free in
// the edges' relaxation; the rest are held where the tile put them.
inline constexpr int edge_band = 3;
// Tiled, the yarn may start this many core diameters deeper into another than the layout
// put it, at most; else the yarn is carried to the tile's places over morph_sweeps
// sweeps (Start::from), where the edges are under half the fabric (see relax_by_repeat).
inline constexpr double deeper_by_tiling = 0.1;
inline constexpr int morph_sweeps = 30;

// The tile (a whole number of the smallest repeat, at least least_tile_wales by
// least_tile_courses loops) of a layout's interior (its loops but the first and last two
// courses and needle positions, and up to most_trimmed more courses at either end that do
// not repeat), if it has one, it fits in the interior, and it has at most half the
// fabric's loops; none for a fabric with tucks. Linear in the fabric for each repeat size
// tried (at most 64 each way).
std::optional<Repeat> find_repeat(const layout::Layout& layout);

// The step of the lattice a layout's repeat lies on, mm: the loop width, or where a
// machine's needles set the positions' widths (a full-needle rib's columns shared by both
// beds, Course::widths) the width most positions take. relax() looks for the repeat in a
// copy of such a layout whose loop_width is this step.
double lattice_step(const layout::Layout& layout);

// Points either side of a period of a course's yarn kept as its images in the periods
// before and after (a tile's run, a strip's).
inline constexpr std::size_t run_handles = 8;

// Whether `points[from, from + period)` is one period of a course's yarn repeating
// `width` mm across: the step to `from + period` is (+-width, 0, 0), and run_handles points
// on either side are the period's images, each to within `close` mm. +1 or -1, the step's
// direction; 0 if not.
int periodic_run(const std::vector<glm::dvec3>& points, std::size_t from, std::size_t period, double width, double close);

// Relaxes `chains` (refined, see refine) by `repeat` with free edges; nothing if the
// pieces do not follow the layout's loops as the tile needs.
std::optional<Relaxed> relax_by_repeat(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains,
                                       const std::vector<yarn::Size>& sizes, const Options& options, const Repeat& repeat);

}  // namespace knitc::relax
