// Tubes: the yarns' cross-sections swept along their curve pieces and gathered into the
// mesh, one primitive and one material per yarn. Curve pieces in, the mesh out. The one
// place that says how many sides and strands a yarn's tube has, and so how many vertices
// a fabric's mesh will have.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "curves/curves.hpp"
#include "mesh/mesh.hpp"
#include "pattern.hpp"
#include "sweep/sweep.hpp"

namespace knitc::tubes {

enum class View {
  surface,     // closed yarn tubes, triangles
  wireframe,   // the tubes' rings and long edges, lines (the paper's Figure 7)
  centreline,  // the sampled centrelines, one line strip per yarn piece (Figure 6)
};

// How a yarn's cross-section is swept.
sweep::CrossSection cross_section(const Yarn& yarn);

// The vertices around each ring of the yarn's tubes for the mesh's `sides` (>= 3): a ply
// is a fraction of the yarn's width, about half the sides do, at least 5.
int ring_sides(const Yarn& yarn, int sides);

// The tubes swept along one piece of the yarn: its plies, or one.
std::size_t strand_count(const Yarn& yarn);

// The vertices of a surface mesh whose piece of `yarn` has `samples` samples, at `sides`.
std::uint64_t vertex_count(const Yarn& yarn, std::size_t samples, int sides);

// "#rrggbb" to linear RGB in [0, 1] (the sRGB transfer function undone), as glTF's
// baseColorFactor wants. The string must be valid: the runtime checks it.
glm::vec3 linear_rgb(const std::string& hex);

// A yarn's colours as linear RGB, each converted once (hot loops colour millions of
// vertices): its dyed runs', its heather's fibres', and its one colour.
struct YarnColours {
  std::vector<glm::vec3> runs;    // one per Yarn::colours
  std::vector<glm::vec3> fibres;  // one per Yarn::heather
  glm::vec3 plain{1.0f};          // Yarn::color
};
YarnColours yarn_colours(const Yarn& yarn);

// The linear RGB of `yarn` (whose colours are `c`) `s` mm from where the knitter started
// it: its colour, or the run of its dyed sequence there (yarn/colour.hpp).
glm::vec3 colour_along(const Yarn& yarn, const YarnColours& c, double s);

// The mm of each piece's yarn before the piece starts: the lengths of that yarn's pieces
// before it, in working order (pieces go yarn by yarn, each in working order).
std::vector<double> yarn_before(std::span<const curves::CurvePiece> pieces);

// A yarn's mean colour: its runs' by length, its heather's by share, else its colour.
glm::vec3 mean_colour(const Yarn& yarn);

// Each yarn's material index: the yarns the pieces use, numbered in the pattern's yarn
// order; -1 for a yarn not used.
std::vector<int> material_indices(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces);

// A material per yarn the pieces use, in the pattern's yarn order (base and sheen colour
// the yarn's mean); returns each yarn's material index, -1 for a yarn not used.
std::vector<int> add_materials(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, mesh::Mesh& mesh);

// The mesh of the pieces, each of yarns[piece.path.yarn]: a material per yarn used (in
// the yarns' order), and per yarn one triangle (surface) or line (wireframe) primitive,
// or a line strip per piece (centreline). A surface's dyed yarns carry a colour per vertex
// (their material white, so the two multiply to the yarn's); a heathered yarn's vertices
// each take a fibre colour by its share, from a hash of the piece and vertex. The same bytes for any
// thread count.
mesh::Mesh build_mesh(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, View view, int sides,
                      int threads);

}  // namespace knitc::tubes
