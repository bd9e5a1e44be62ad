// Tiles: a fabric whose interior repeats, meshed once per repeat and placed many times
// (glTF's EXT_mesh_gpu_instancing). The lattice of cells comes from the relaxation's
// repeat; a cell is instanced only where its samples are the reference cell's moved by one
// translation (checked, sample by sample), and everything else (edges, shaping, what does
// not repeat) is meshed plainly, cut at the very samples the tiles start and end at.
// Curve pieces in, a mesh with instances out.
#pragma once

#include <span>
#include <string>

#include "curves/curves.hpp"
#include "layout/layout.hpp"
#include "mesh/mesh.hpp"

namespace knitc::tiles {

// The cells: blocks of `wales` x `courses` loops, the first at (wale0, course0).
struct Lattice {
  int wales = 0, courses = 0, wale0 = 0, course0 = 0;
};

// A cell is instanced when each of its samples lies within this of the reference cell's
// moved by the cell's translation (mm), and its tangents and pressing agree as closely.
inline constexpr double same_place = 1e-4;

struct Tiling {
  mesh::Mesh mesh;             // the edges as plain primitives, the tile in mesh.instanced
  std::size_t cells = 0;       // cells placed (the reference's among them)
  std::size_t complete = 0;    // cells with all their loops in the fabric
  std::string declined;        // why nothing was instanced (then mesh is empty)
};

// The mesh of `pieces` (the curves stage's, of the smooth model, flat work) with every
// cell of `lattice` that repeats the reference cell (the complete one nearest the fabric's
// middle) instanced. Tiles meet their neighbours and the edges ring for ring: every cut is
// at a loop's first sample, where both sides' sections are the same and their seams are
// put at one angle (sweep::seam_angle), turned linearly along each stretch between cuts;
// u runs along each stretch from 0 to its length in mm rounded to a whole number, so a
// texture repeating every millimetre carries across. Caps only at the yarn's ends. The
// same bytes for any thread count.
Tiling tile(std::span<const Yarn> yarns, const layout::Layout& layout, std::span<const curves::CurvePiece> pieces,
            const Lattice& lattice, int sides, int threads);

// Every instance written out as plain triangles, into its material's primitive: what a
// reader without the extension, a printer or a simulation wants. Each copy is the tile's
// vertices plus its translation, in float, so it lies on its tile exactly.
mesh::Mesh flatten(const mesh::Mesh& mesh, int threads);

// Triangles and vertices the mesh draws, with every instance counted.
struct Drawn {
  std::uint64_t triangles = 0, vertices = 0, stored_vertices = 0;
};
Drawn drawn(const mesh::Mesh& mesh);

}  // namespace knitc::tiles
