// The compiler's pipeline, wired: Pattern -> Layout -> yarn paths -> NURBS curves ->
// sweep -> Mesh. Each stage is a function of plain data; this file only runs them in turn.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "layout/layout.hpp"
#include "mesh/mesh.hpp"
#include "nurbs/nurbs.hpp"
#include "pattern.hpp"
#include "relax/relax.hpp"
#include "sweep/sweep.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc {

enum class View {
  surface,     // closed yarn tubes, triangles
  wireframe,   // the tubes' rings and long edges, lines (the paper's Figure 7)
  centreline,  // the sampled centrelines, one line strip per yarn piece (Figure 6)
};

// Mesh density: vertices around each ring, and the chord error of the surface along
// the yarn as a fraction of the yarn's diameter.
enum class Quality { draft, normal, fine };
struct Density {
  int sides;
  double chord_tolerance;
};
Density density(Quality quality);  // draft: 6, 5%; normal: 12, 1%; fine: 24, 0.25%

struct CompileOptions {
  yarn_paths::LoopModel loop_model = yarn_paths::LoopModel::smooth;
  nurbs::Parametrisation parametrisation = nurbs::Parametrisation::chord_length;
  View view = View::surface;
  int sides = 12;                 // vertices per tube ring, >= 3 (plies get about half, at least 5)
  double chord_tolerance = 0.01;  // as a fraction of the yarn diameter, > 0
  // Contact relaxation after the layout (see relax/relax.hpp); off: the layout's curves as
  // they are. Off by default until it holds for every fabric (docs/relaxation.md).
  bool relax = false;
  relax::Options relaxation;
  int threads = 0;                // 0: every core; the result is the same for any count
  // Called with a stage's name and how far it is, in [0, 1], from any thread (so it must
  // be thread-safe); for a progress display. It never changes the result.
  std::function<void(const char* stage, double fraction)> progress;
};

// One yarn piece through the stages: its data points, its curve, its samples.
struct CurvePiece {
  yarn_paths::Piece path;
  nurbs::Interpolant curve;
  std::vector<double> samples;  // curve parameters, increasing
  sweep::Frames frames;         // one per sample; frames.origin are the centreline samples
  std::vector<double> arc_length;  // the yarn's length in mm from the piece's start, per sample
  // Loop j of the piece owns samples [loop_samples[j].first, loop_samples[j].second]
  // (both ends: loops that meet share their join sample). Size: path.loops.size().
  std::vector<std::pair<std::size_t, std::size_t>> loop_samples;
};

struct Fabric {
  layout::Layout layout;
  std::vector<CurvePiece> pieces;
  mesh::Mesh mesh;
  bool relaxed = false;
  relax::Stats relaxation;      // when relaxed
  double relax_seconds = 0.0;   // wall time of the relaxation; not part of any output file
};

// The frames each loop model sweeps with: Frenet for the paper's, rotation-minimising
// for the smooth one.
sweep::FrameKind frame_kind(yarn_paths::LoopModel model);

// Sizes past which compile() refuses a fabric rather than run out of memory: about
// 14 GB at peak on the way to the file, and the loops that take minutes before the mesh is even sized.
inline constexpr std::uint64_t max_vertices = 80'000'000;
inline constexpr std::uint64_t max_loops = 2'000'000;

// A pattern the compiler cannot make geometry for (yet). what() is "file:line: ...".
class CompileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Compiles a validated pattern (the runtime validates) into geometry. Throws
// CompileError for a fabric past the size limits.
Fabric compile(const Pattern& pattern, const CompileOptions& options);
// The stages after the layout, on a given one (its loops' data points may be changed):
// yarn paths, curves, sweep, mesh.
Fabric compile(const Pattern& pattern, layout::Layout layout, const CompileOptions& options);

// How a yarn's cross-section is swept.
sweep::CrossSection cross_section(const Yarn& yarn);

// "#rrggbb" to linear RGB in [0, 1] (the sRGB transfer function undone), as glTF's
// baseColorFactor wants. The string must be valid: the runtime checks it.
glm::vec3 linear_rgb(const std::string& hex);

}  // namespace knitc
