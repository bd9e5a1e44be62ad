// The relaxation's working form of the yarns: every piece's points in one array, with
// what each point and segment is. Internal to relax/.
#pragma once

#include <cstdint>
#include <vector>

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
  double thickest = 0.0;                  // mm, the largest free diameter
  double thickest_core = 0.0;             // mm, the largest core diameter
};

// The pieces' points as chains. Held boundaries give the cast-on's and the last course's
// loops no mobility; periodic ones leave the points off every loop (turns at the
// selvedge, tails) out of the contacts.
Chains chains_of(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& pieces,
                 const std::vector<yarn::Size>& sizes, Boundary boundary);

}  // namespace knitc::relax
