// The edges of a fabric relaxed by its repeat, as strips periodic along each edge (issue
// 18). Where the loops the tile does not hold form a frame (a band along the cast-on, the
// last course and each selvedge, as plain fabric's do), each band is relaxed as one
// repeat of an endless strip: the band's loops over one tile's width (or height), with
// two courses (or wales) of the held interior beside them, their contacts wrapping along
// the edge. The relaxed strip is copied along its edge, and only the corners are left to
// relax against the copies. The work grows with the tile and the band's depth, not the
// edge's length. Internal to relax/.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "relax/chains.hpp"
#include "relax/repeat.hpp"

namespace knitc::relax {

// The fabric's loops by place: at[course * wales + wale], -1 where there is none.
struct LoopGrid {
  int courses = 0, wales = 0;
  std::vector<long> at;
  // Work in the round (else empty): per course, its needle positions. Past a round's last
  // lies the next round's first, beside it on the tube (the yarn spirals: the loop left
  // of wale 0 is the next course's last, the one right of a course's last the course
  // before's wale 0).
  std::vector<int> round_needles;
  long operator()(int course, int wale) const {
    if (!round_needles.empty() && courses > 0) {
      // (A course past either end, asked for by a neighbourhood, goes round as the nearest.)
      auto needles = [&](int c) { return round_needles[static_cast<std::size_t>(std::clamp(c, 0, courses - 1))]; };
      while (wale < 0) {
        if (needles(++course) <= 0) return -1;
        wale += needles(course);
      }
      while (wale >= needles(course)) {
        if (needles(course) <= 0) return -1;
        wale -= needles(course--);
      }
    }
    if (course < 0 || course >= courses || wale < 0 || wale >= wales) return -1;
    return at[static_cast<std::size_t>(course) * static_cast<std::size_t>(wales) + static_cast<std::size_t>(wale)];
  }
};

// The layout's loops by course and wale (a tube's running on past each round's start).
LoopGrid grid_of(const layout::Layout& layout);

struct Strips {
  int relaxed = 0;         // strips relaxed and copied (0 to 4)
  int iterations = 0;      // the most sweeps one took
  double end_overlap = 0;  // the deepest core overlap one left, of the thickest core d
  // Per point of the fabric they placed, in no order: the point, and the relaxed strips'
  // point it is a copy of (the strips' points numbered one after another, `numbered` in all).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> copies;
  std::uint32_t numbered = 0;
};

// Relaxes the bands of `start` (the tiled start of relax_by_repeat: every point's place,
// held where the tile put it) that form a frame round the held interior, periodic with
// `period` (mm, the tiled lattice's repeat, stretched as the tile was), and writes each
// strip's copies into start, held. loop_held: per loop of the layout, whether the tile
// holds it. Nothing is changed where the bands do not form a frame, a band is too short
// to be worth a strip, or its loops do not repeat along it.
Strips relax_strips(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains, const std::vector<yarn::Size>& sizes,
                    const Options& options, const Repeat& repeat, glm::dvec2 period, const LoopGrid& grid,
                    const std::vector<std::uint8_t>& loop_held, Start& start);

}  // namespace knitc::relax
