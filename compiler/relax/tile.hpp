// The tile a fabric relaxed by its repeat (repeat.hpp) is relaxed as, cut from the fabric,
// and the move its relaxation gives each point of the fabric. Internal to relax/.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "relax/chains.hpp"
#include "relax/relax.hpp"
#include "relax/repeat.hpp"
#include "relax/strips.hpp"

namespace knitc::relax {

// Whether loop b is laid out as loop a moved by (wales, courses) of the lattice: the same
// stitch, shape, yarn and direction, and every data point moved by the same step.
bool repeats(const layout::Layout& layout, long a, long b, int wales, int courses);

// a / b rounded down (b > 0).
inline int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
// a's place in a period of `period` (0 <= it < period); a itself where there is no period.
inline int in_period(int a, int period) { return period > 0 ? a - floor_div(a, period) * period : a; }

// The tile: the repeat's block of loops as a layout of its own, and each piece's runs of
// them (consecutive loops of one course, with what lies between them) as its pieces, each
// course's yarn running on through images of itself a period on either side (`links`).
// Nothing where a loop of the block belongs to no piece.
struct Tile {
  layout::Layout layout;
  std::vector<yarn_paths::Piece> pieces;
  std::vector<std::pair<long, long>> owner;                   // fabric loop -> its piece, and its loop there
  std::vector<long> tile_loop;                                // fabric loop -> tile loop, or -1
  std::vector<std::pair<std::size_t, std::size_t>> where_in_tile;  // tile loop -> tile piece, loop
  std::vector<std::size_t> run_period_end;  // per tile piece: where its image a period on starts (0: none)
  Start links;
};

std::optional<Tile> cut_tile(const layout::Layout& layout, const LoopGrid& g, const std::vector<yarn_paths::Piece>& chains,
                             const Repeat& repeat);

// The whole fabric stretched as the tile was, about `origin` (mm): a point's move.
struct LatticeStretch {
  glm::dvec3 origin;
  glm::dvec2 stretch;  // the lattice's, per axis
  glm::dvec3 operator()(const glm::dvec3& p) const {
    return glm::dvec3((p.x - origin.x) * (stretch.x - 1.0), (p.y - origin.y) * (stretch.y - 1.0), 0.0);
  }
};

// Every point's own move (over the lattice's stretch, `affine`): a tiled loop's is its
// tile loop's, where it and its neighbours two loops round are laid out as their tile
// loops; the others' are blended along their yarn between the nearest tiled points.
struct Moves {
  // A tiled loop's points, [first, first + count) of its piece, and their tile points,
  // from run_first of the tile's piece `run` on.
  struct Span {
    std::uint32_t piece, first, count, run, run_first;
  };
  std::vector<std::vector<glm::dvec3>> local;         // per piece and point
  std::vector<std::vector<std::uint8_t>> tiled;       // per piece and point: moved as its tile point
  std::vector<std::vector<std::uint32_t>> tile_point; // per tiled point, its tile point (the tile's pieces' points in order), else no_tile_point
  std::vector<std::uint32_t> tile_first;              // per tile piece, its first point there; then the end
  std::vector<std::uint8_t> loop_tiled;               // per loop
  std::vector<Span> spans;                            // per tiled loop, in the loops' order
};
inline constexpr std::uint32_t no_tile_point = UINT32_MAX;

// The arrays of Moves for `chains` and `loops` loops, every point unmoved and untiled:
// made apart from tile_moves, so that they can be while the tile relaxes.
Moves unmoved(const std::vector<yarn_paths::Piece>& chains, std::size_t loops);
// Which loops are tiled, and as which tile loops: all of `out` but its moves (`local`),
// made as unmoved(chains, layout.loops.size()) made it. Reads the tile as cut, not as
// relaxed, so it can be made while the tile relaxes.
void tile_places(const layout::Layout& layout, const LoopGrid& g, const std::vector<yarn_paths::Piece>& chains, const Repeat& repeat,
                 const Tile& cut, Moves& out);
// Then every point's move, from the relaxed tile: `relaxed_tile` has cut's pieces' points.
void tile_moves(const Tile& cut, const Relaxed& relaxed_tile, const LatticeStretch& affine, Moves& out);

// Per loop of the layout: whether the tiled start holds it (tiled, with nothing untiled
// within edge_band loops either way), and how many loops, across or up, the nearest loop
// not held (or a place with no loop) is, at most far_from_free.
inline constexpr int far_from_free = edge_band + 3;
struct HeldLoops {
  std::vector<std::uint8_t> held, to_free;
};
HeldLoops held_loops(const layout::Layout& layout, const LoopGrid& g, const std::vector<std::uint8_t>& loop_tiled);

}  // namespace knitc::relax
