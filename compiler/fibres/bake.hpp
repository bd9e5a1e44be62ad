// Baked yarn: the fibre model's surface (yarn/fibres.hpp) as maps on the plain tube, so any
// glTF viewer shows plies and fibres on a cheap mesh. Per yarn, one tile of its surface
// over one turn of its plies: a height field of the plies (each an ellipse where it crosses
// the yarn's section, slanted by its helix) and of the surface fibres on them (ridges a
// fibre wide, twisted about their ply), from which a normal map (slopes of the heights, in
// mm over mm), an occlusion map (the sky each texel sees over the heights round it, the
// tube's own curvature included) and a colour map (each fibre's shade, or its heather
// colour) follow. A yarn swept as plies (section "plied") already has its plies in the mesh:
// its tile is one ply's fibres, wrapped round each ply's tube.
#pragma once

#include <span>

#include "curves/curves.hpp"
#include "mesh/mesh.hpp"
#include "pattern.hpp"

namespace knitc::fibres {

// Texels of a tile: along the yarn, and round it. Fibres narrower than four texels are drawn
// as bundles four texels wide (the texture says the fibres' direction and shade, not each).
inline constexpr int tile_along = 256, tile_round = 256;

struct BakedYarn {
  mesh::Image normal, occlusion, colour;  // tile_along x tile_round; colour sRGB-encoded
  double length = 0.0;                    // mm of yarn the tile spans (u repeats every `length`)
  int fibres_round = 0;                   // surface fibres (or bundles) round each ply
  int fibre_turns = 0;                    // turns each fibre makes about its ply in the tile
};

// One yarn's tile, on up to `threads` threads (0: every core). Deterministic: the fibres'
// shades are hashed from their ply, place and stretch; the same bytes for any thread count.
BakedYarn bake(const Yarn& yarn, int threads = 0);

// Bakes each yarn the mesh's materials draw (their order is tubes::material_indices') and
// gives its material the three maps; a heathered yarn's colours move into its colour map
// and its material turns white, as the tube then carries no colour per vertex.
void add_baked_textures(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, mesh::Mesh& mesh,
                        int threads);

}  // namespace knitc::fibres
