// The relaxation's working form of the yarns: every piece's points in one array, with
// what each point and segment is. Internal to relax/.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "relax/relax.hpp"

namespace knitc::relax {

// Segment i joins point i to point i + 1 when both are on the same piece.
struct Chains {
  std::vector<glm::dvec3> pos;   // mm, where each point is now
  std::vector<glm::dvec3> rest;  // mm, where the layout put it
  std::vector<double> radius;    // mm, the yarn's core: no contact comes closer
  std::vector<double> shell;     // mm, the yarn's free radius: closer, its shell compresses
  std::vector<double> along;     // mm along its piece, in the layout
  std::vector<double> inv_mass;  // 0: held in place; 1: free
  std::vector<std::uint32_t> piece;
  std::vector<std::uint8_t> on_loop;      // 1: the point is on some loop (not a tail or a turn)
  std::vector<std::uint8_t> segment;      // 1: point i and i + 1 are joined
  std::vector<std::uint8_t> contactable;  // per segment: takes part in contacts
  std::vector<double> rest_length;        // per segment, mm
  std::vector<std::size_t> first;         // per piece, its first point; then one past the end
  // Per piece: how far along it (mm) its image one period on in x lies, when the piece's
  // yarn runs on into the next tile (see Image); 0 when it does not.
  std::vector<double> along_period;
  double thickest = 0.0;                  // mm, the largest free diameter
  double thickest_core = 0.0;             // mm, the largest core diameter
};

// The pieces' points as chains. Held boundaries give the cast-on's and the last course's
// loops no mobility; periodic ones leave the points off every loop (turns at the
// selvedge, tails) out of the contacts.
Chains chains_of(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& pieces,
                 const std::vector<yarn::Size>& sizes, Boundary boundary);

// What the sweeps are given beside the layout: where they start (every chain point's
// position, in chains_of's order, and whether it is held there; empty: the layout's, none
// held; the rest lengths stay the layout's), and periodic images: points kept, after every
// sweep, at another point moved `across` periods in x (a tile's yarn running on into the
// next tile, so that its edge loops are pulled as the middle ones are).
struct Image {
  std::uint32_t point, source;
  std::int8_t across;
};
struct Start {
  std::vector<glm::dvec3> pos;
  std::vector<std::uint8_t> held;
  std::vector<Image> images;
  // A block of a fabric periodic along an edge (a strip, relax/strips.hpp): its contacts
  // wrap this far in x or y (mm; 0: not that way), and its held points keep the period.
  glm::dvec2 period{0.0};
  // Empty, or where every point starts (a tiled start's places before the tile's own
  // moves): the held points are then carried from there to `pos` over `morph_sweeps`
  // sweeps, a step a sweep, and the free ones pushed along by the contacts, which keep
  // each crossing's side, rather than jumped there at once (relax_by_repeat, where the
  // jump would leave the yarns too deep into each other).
  std::vector<glm::dvec3> from;
  int morph_sweeps = 0;
};

// The sweeps on the chains of `pieces` (see relax.hpp), from the layout or from `start`.
// A held interior keeps the fabric's size.
Relaxed relax_chains(const layout::Layout& layout, std::vector<yarn_paths::Piece> pieces, const std::vector<yarn::Size>& sizes,
                     const Options& options, const Start* start);

}  // namespace knitc::relax
