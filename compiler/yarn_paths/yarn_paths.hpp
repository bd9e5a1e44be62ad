// Yarn paths: the data points each yarn piece passes through, in order along the yarn,
// in fabric coordinates. A piece is a run of yarn that becomes one NURBS curve and one
// closed tube.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "layout/layout.hpp"

namespace knitc::yarn_paths {

enum class LoopModel {
  paper,   // each loop its own curve through its 17 points, as the seed paper does it
  smooth,  // each yarn one curve through all its loops, floats and turns: C2 along the yarn
};

struct Piece {
  int yarn = 0;                          // index into Pattern::yarns
  std::vector<glm::dvec3> data_points;   // mm, fabric coordinates, no two consecutive equal
  // The loops along the piece in working order, as indices into Layout::loops. Loop j
  // passes through data_points[loop_first[j] .. loop_last[j]] (its P0..P16, or P16..P0
  // when worked right to left; as traced, loop_last[j] = loop_first[j] + 16, more once
  // the relaxation has refined the piece). Points outside every loop are floats, turns at
  // the selvedge and tails.
  std::vector<int> loops;
  std::vector<std::size_t> loop_first, loop_last;
  // Once relaxed, per data point (else empty: round): the direction the yarn is pressed
  // from, across it, of length 1 - its section's aspect (relax/press.hpp).
  std::vector<glm::dvec3> pressed;
};

inline constexpr int points_per_loop = layout::loop_points - 1;

// The smooth model: a piece per yarn from its first loop to its last, turning at the
// selvedge between rows of flat work and spiralling in the round, floating behind (or in
// front of) the needle positions it passes by; a course that does not use the yarn cuts
// it, and every piece starts and ends with a short tail behind the fabric. Pieces go
// yarn by yarn in the pattern's yarn order, each yarn's in working order.
// The paper model: a piece per loop, loops in layout order; no floats, turns or tails.
std::vector<Piece> trace(const layout::Layout& layout, LoopModel model);

}  // namespace knitc::yarn_paths
