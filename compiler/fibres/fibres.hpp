// Fibres: a yarn's procedural fibres (yarn/fibres.hpp) laid along its curve pieces, for
// close-ups (--section fibres). Each ply is drawn as a solid core, a tube at `core` of the
// ply's radius, so the fabric does not show through between the fibres drawn (a real ply
// holds hundreds); round it, every fibre as line segments that follow its ply's twist and
// migrate in and out; and the flyaways, loops and hairs, off the yarn's surface.
// Curve pieces in, a mesh out.
#pragma once

#include <cstdint>
#include <span>

#include "curves/curves.hpp"
#include "mesh/mesh.hpp"
#include "pattern.hpp"

namespace knitc::fibres {

// A ply's solid core, as a fraction of the ply's radius: the fibres sit from about here out,
// and the core keeps the yarn its width where its fibres are thinner than a pixel.
inline constexpr double core = 0.85;
// The longest a fibre's segment is (mm); shorter where its twist turns it faster.
inline constexpr double max_step = 0.2;

// The line vertices the fibres and flyaways of `pieces` will have: for refusing a mesh past
// knitc's limit before it is made. Exact.
std::uint64_t fibre_vertices(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces);

// The mesh: per yarn used, a material (as tubes::add_materials), a triangle primitive of
// its plies' cores at `sides` (>= 3), and a line primitive of its fibres and flyaways whose
// line_radius is half the fibre diameter. A dyed yarn's vertices carry its colour along the
// yarn (tubes::colour_along). The fibres' places are drawn from a hash of the yarn, piece,
// ply and fibre, so the same bytes come for any thread count.
mesh::Mesh build_mesh(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, int sides, int threads);

}  // namespace knitc::fibres
