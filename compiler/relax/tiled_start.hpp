// The tiled start's cuts and checks: a fabric relaxed by its repeat (repeat.hpp) starts
// from the tile copied across it, held, with the edges free. What of it the edges'
// relaxation must see (the crop), where held yarn still overlaps and is freed, and whether
// the tiling left the yarn deeper into itself than the layout did. Internal to relax/.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "layout/layout.hpp"
#include "relax/chains.hpp"

namespace knitc::relax {

// Every point of `chains` (in order): its place along its piece (mm) and its piece; per
// piece its core radius; the thickest free diameter. What free_where_held_overlap needs
// of the laid fabric alone, so that it can be listed while the tile relaxes.
struct AlongYarn {
  std::vector<double> along, piece_core;
  std::vector<std::uint32_t> piece;
  double thickest = 0.0;
};
AlongYarn along_yarn(const std::vector<yarn_paths::Piece>& chains, const std::vector<yarn::Size>& sizes);

// The tile's shape is trusted where a loop's neighbourhood is laid out as its tile
// loop's; where two held stretches of yarn still pass into each other (a loop laid out as
// its tile loop whose neighbours along the yarn are not), both are freed, a loop's length
// of yarn either way, for the edges' relaxation to clear. Only near what is not held can
// that be: the held points each a copy of its tile point, among copies, lie as the tile's
// (relaxed apart) do. So the points looked from are `look_from`'s, and the points looked
// at `look_at`'s (a wider band: the held points close to the first).
void free_where_held_overlap(const AlongYarn& yarn, Start& start,
                             const std::vector<std::uint8_t>& look_from, const std::vector<std::uint8_t>& look_at, int threads);

// The edges' relaxation needs only what it can move and what it touches: the free points,
// the held ones within `reach` (mm) of one, and, so that every loop stays whole and a
// point's neighbours along the yarn are there for bending, whole loops round them. The
// rest stays where the tile put it. Per piece, its runs of needed points as pieces of
// their own (a run's own loops), where each run starts in the piece, and their start.
struct Crop {
  std::vector<yarn_paths::Piece> pieces;
  std::vector<std::pair<std::size_t, std::size_t>> origin;  // per run: piece, first point
  Start start;
  std::vector<std::uint8_t> needed;  // per point of the fabric: 1 free, 2 held within reach of a free one, 0 neither
};

// Per point: 1 free, 2 held within `reach` (mm) of a free one, 0 neither; the same on any
// number of threads.
std::vector<std::uint8_t> near_free(const Start& start, double reach, int threads);

// `needed`: near_free's.
Crop crop(const std::vector<yarn_paths::Piece>& chains, const Start& start, std::vector<std::uint8_t> needed);

// Whether `start` (a tiled start: every point of `laid`'s pieces, in order, held or not)
// leaves two cores deeper into each other, among the pairs with a point free, than
// deeper_by_tiling (repeat.hpp) core diameters past the deepest the layout `laid` has: tiling jumps the
// yarn to the tile's places with no sweep between to keep its crossings, and a deep
// overlap pushed out may come out on the wrong side.
bool deeper_than_laid(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& laid, const std::vector<yarn::Size>& sizes,
                      const Start& start, int threads);

}  // namespace knitc::relax
