// Layout: a loop instance per stitch, placed on the fabric. Millimetres; the fabric lies
// in the XY plane, +X along a course (wale index grows), +Y up the wales (course index
// grows), +Z out of the technical face.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "pattern.hpp"

namespace knitc::layout {

// The plain loop of the seed paper (Table 1): 17 data points from one sinker loop (P0)
// up a leg, over the needle loop (P8) and down to the next sinker loop (P16), as
// fractions of loop width W (x), loop height H (y) and thickness T (z).
inline constexpr int loop_points = 17;
std::span<const glm::dvec3, loop_points> plain_loop_fractions();

// The plain loop's data points in mm for a gauge, with P0 at the origin.
std::array<glm::dvec3, loop_points> plain_loop(const Gauge& gauge);

struct Loop {
  int course = 0;
  int wale = 0;
  StitchId stitch = 0;
  int yarn = 0;  // index into Pattern::yarns
  std::array<glm::dvec3, loop_points> data_points;  // mm, fabric coordinates
};

struct Layout {
  int courses = 0;
  int wales = 0;
  std::vector<Loop> loops;  // course by course, left to right within a course
};

// Places loop (course c, wale w) with its P0 at (w W, c C, 0). Loops of a course share
// end points: P16 of one is P0 of the next. A purl loop is the knit loop seen from the
// back: its z is mirrored. The pattern must hold only stitches can_lay_out accepts.
Layout lay_out(const Pattern& pattern);

// Whether the layout has a template for the stitch yet (knit and purl so far).
bool can_lay_out(StitchId stitch);

}  // namespace knitc::layout
