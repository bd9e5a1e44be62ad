// Measuring, a stage of its own: how long each yarn is, how deep distinct parts of the
// yarns pass into each other, how tightly the tubes bend, how fast the sweep's frames
// turn, and the loops' shape. Plain numbers from the layout and the curve pieces, for
// `knitc build --stats` and the snapshots (whose writer takes them as an argument).
#pragma once

#include <span>
#include <vector>

#include "curves/curves.hpp"
#include "layout/layout.hpp"
#include "pattern.hpp"

namespace knitc::measure {

struct FabricMeasures {
  std::size_t loops = 0, pieces = 0;
  std::vector<double> yarn_length;  // mm, per Pattern::yarns entry (0 for a yarn not used)
  // The deepest overlap of two yarn tubes, as a fraction of the yarn diameter: the
  // largest (r_a + r_b - distance) / d over pairs of centreline points of different
  // pieces, or of one piece more than two diameters apart along it. The centrelines are
  // taken at the sweep's samples, filled in to a quarter diameter apart. 0: no overlap.
  double deepest_penetration = 0.0;
  // The same for the yarns' compact cores (Yarn::core_diameter): the deepest
  // (c_a + c_b - distance) of the core radii, over the thickest core diameter. The shells
  // between core and free surface compress (docs/yarn.md); the cores must not meet.
  double deepest_core_penetration = 0.0;
  // The smallest radius of curvature of any centreline, over its tube's radius (for a
  // flattened or plied yarn, half its width): below 1 the tube folds on itself.
  // Infinite for centrelines that are straight throughout.
  double tightest_bend = 0.0;
  double largest_frame_turn = 0.0;  // degrees, between consecutive sweep frames
};

// Linear in the fabric: a spatial hash of cells one diameter wide finds the close pairs.
FabricMeasures measure(const Pattern& pattern, const layout::Layout& layout, std::span<const curves::CurvePiece> pieces);

// The shape of the fabric's inner loops, in the terms of Munden (1959): the loop length
// l (yarn per stitch, sinker loop to sinker loop), the distances between the centres
// (mean sample) of neighbouring loops along a course (wale spacing) and along a wale
// (course spacing), and the loop-shape factors kc = l x courses per mm and kw = l x wales
// per mm. Inner: neither in the first two nor the last two courses, nor in the first or
// last two needle positions of their course, and with the same neighbours there. Zero
// when the fabric has no inner loops.
struct LoopShape {
  std::size_t loops = 0;  // inner loops measured
  double loop_length = 0.0, wale_spacing = 0.0, course_spacing = 0.0;  // mm, means
  double kc = 0.0, kw = 0.0;
  // Flat work, in the fabric's plane: the mean distance across (x) between neighbouring
  // loops' centres, and up (y); a rib's purl wale recessed behind its knit neighbours is
  // close across though far in depth. mm.
  double wale_pitch = 0.0, course_pitch = 0.0;
  // The depth (z) the inner loops' centrelines span, mm: the fabric's thickness less a
  // yarn's diameter.
  double depth = 0.0;
};
LoopShape loop_shape(const layout::Layout& layout, std::span<const curves::CurvePiece> pieces);

}  // namespace knitc::measure
