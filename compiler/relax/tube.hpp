// A tube relaxed by its repeat: its chains unrolled into the layout's own flat frame
// (layout::unroll), where its interior repeats as flat work's does, the tile cut and
// relaxed there, and every point's move rolled back onto the tube (repeat.cpp). Internal
// to relax/.
#pragma once

#include <vector>

#include "layout/layout.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc::relax {

// The least needle positions round a tube relaxed by its repeat: the tile is relaxed flat,
// and bent round a tube narrower than this its shape would no longer be the tile's (the
// tube's curvature over a 4-loop tile turns it by more than 60 degrees).
inline constexpr int least_round_wales = 24;

struct Unrolled {
  std::vector<yarn_paths::Piece> pieces;           // the chains, each point in the layout's flat frame
  std::vector<std::vector<double>> circumference;  // per piece and point: its course's, mm
};

// `chains`: work in the round, each point on the loops of `layout` as yarn_paths traced
// and relax::refine refined them. A point on a loop is unrolled by its loop's course, next
// to the loop's place; one between loops by the nearer loop's along the yarn (round the
// turn from one round to the next, either: each rolls back onto the same point).
Unrolled unroll(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains);

}  // namespace knitc::relax
