// Yarn paths: the data points each yarn piece passes through, in order along the yarn.
// A piece is a run of yarn that becomes one NURBS curve and one closed tube.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "layout/layout.hpp"

namespace knitc::yarn_paths {

enum class LoopModel {
  paper,   // each loop its own curve through its 17 points, as the seed paper does it
  smooth,  // each course one curve through all of its loops' points: C2 along the yarn
};

struct Piece {
  int yarn = 0;                          // index into Pattern::yarns
  std::vector<glm::dvec3> data_points;   // mm
  // The loops along the piece, as indices into Layout::loops. Loop j of the piece
  // passes through data_points[16 j .. 16 (j + 1)].
  std::vector<int> loops;
};

inline constexpr int points_per_loop = layout::loop_points - 1;

// Pieces in a fixed order: course by course, left to right.
std::vector<Piece> trace(const layout::Layout& layout, LoopModel model);

}  // namespace knitc::yarn_paths
