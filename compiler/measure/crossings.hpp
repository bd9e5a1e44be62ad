// The fabric as a knot diagram: where two stretches of yarn cross, seen from the face
// (along -z), and which passes in front. For flat work, or a tube unrolled into its
// layout's flat frame (relax::tube_as_flat). Tells whether a change to the geometry (the
// relaxation) kept every yarn on its side of every other.
#pragma once

#include <cstdint>
#include <vector>

#include "yarn_paths/yarn_paths.hpp"

namespace knitc::measure {

struct Crossing {
  // Segment k of a piece joins its data points k and k + 1. (piece_a, segment_a) is
  // before (piece_b, segment_b) in that order.
  std::uint32_t piece_a = 0, segment_a = 0, piece_b = 0, segment_b = 0;
  double depth = 0.0;  // mm, z of a minus z of b where they cross: > 0, a is in front
};

// Every crossing of two segments' projections onto the xy plane, but of two segments of
// one piece less than `near` data points apart along it (a yarn's own bends). Ordered by
// (piece_a, piece_b, segment_a, segment_b). A grid of cells one segment long: linear.
// threads >= 1 (0: every core); the result is the same for any count. `looked_at`, empty
// or per piece one flag per data point: only crossings where a segment's flag is not 0.
std::vector<Crossing> crossings(const std::vector<yarn_paths::Piece>& pieces, std::uint32_t near = 2, int threads = 1,
                                const std::vector<std::vector<std::uint8_t>>& looked_at = {});

struct CrossingChanges {
  std::size_t kept = 0;     // matched, same yarn in front
  std::size_t flipped = 0;  // matched, the other yarn in front
  std::size_t lost = 0;     // before with no match after
  std::size_t found = 0;    // after with no match before
  std::size_t ties = 0;     // before at one height (|depth| < 1 um): no side to keep, left out
  // Of the lost (and of the new): those that do not pair up with another lost (new) one
  // between the same pieces within the window, the same yarn in front. Two crossings of
  // one yarn over another may vanish or appear together as the yarns slide apart or
  // together (Reidemeister's second move) with nobody passing through anybody; a lone
  // one cannot.
  std::size_t lost_alone = 0, found_alone = 0;
  std::vector<std::size_t> lost_alone_at, found_alone_at;  // their indices in before, after
  // Of those, the ones where the two yarns touched (|depth| below `touching`, mm, as
  // compare was given it): only there can one have passed through the other. Where they
  // lay a diameter apart the crossing slid away or in, its partner out of reach.
  std::size_t lost_alone_touching = 0, found_alone_touching = 0;
  // Lost or new alone within the pair window of a yarn's free end (given the pieces'
  // lengths): an end sliding past another yarn unmakes or makes one crossing alone, with
  // nobody passing through anybody. Not counted in lost_alone or found_alone.
  std::size_t lost_at_end = 0, found_at_end = 0;
  // Counted only where a segment is not a copy of the tile's or an edge strip's
  // (relaxation_changes's same_as): the copies cross as their first copy does.
  bool copies_left_out = false;
};

// Matches crossings before to crossings after between the same two pieces within
// `window` segments along each (the pieces' points must correspond, as the relaxation
// keeps them), one to one, nearest first, and counts what became of them. The unmatched
// pair off within `pair_window` segments (0: the same window): two crossings a move of
// Reidemeister's second kind makes or undoes can lie further apart than one crossing
// slides, as where a float slides under the legs of two neighbouring loops.
// `segments`, if given, is each piece's number of segments: its ends are free, so a lone
// change near one is an end's (lost_at_end, found_at_end). `counted_before` and
// `counted_after`, empty or one flag per crossing: the others only match and pair with
// the counted, and are not counted themselves (a matched pair counts if either does).
CrossingChanges compare(const std::vector<Crossing>& before, const std::vector<Crossing>& after, std::uint32_t window,
                        std::uint32_t pair_window = 0, double touching = 0.0, const std::vector<std::uint32_t>& segments = {},
                        const std::vector<char>& counted_before = {}, const std::vector<char>& counted_after = {});

// The relaxation's changes to the knot diagram: `laid`, the refined layout's chains
// (relax::refine), and `relaxed`, the same points moved. Matched within 12 segments
// (about 8 core diameters: the chains' points are 0.7 apart), the unmatched paired off
// within 24 (a float sliding under two neighbouring loops' legs makes two crossings some
// 3 mm apart along their yarn); `thickest`, the thickest free diameter, mm: where the
// yarns lay further apart in depth, a crossing lost or found alone slid away or in. A
// lone change within 24 segments of a yarn's end is the end's (a tail drawn back).
// `same_as`, empty or per point (relax::Relaxed::same_as): a point of the held interior,
// or of an edge's strip, whose surroundings, laid and relaxed, are another's moved by
// whole tiles. Only crossings at a segment with an end of its own are counted (the copies
// cross as their first copy does), matched against those within reach along the yarn.
CrossingChanges relaxation_changes(const std::vector<yarn_paths::Piece>& laid, const std::vector<yarn_paths::Piece>& relaxed,
                                   double thickest, int threads = 1, const std::vector<std::uint32_t>& same_as = {});

// The crossings a yarn passing through another would explain: flipped, or lost or found
// alone where the two yarns touched.
inline std::size_t passed_through(const CrossingChanges& c) {
  return c.flipped + c.lost_alone_touching + c.found_alone_touching;
}

}  // namespace knitc::measure
