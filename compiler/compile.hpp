// The compiler's pipeline, wired: Pattern -> layout -> yarn paths -> (relax) -> curves
// -> tubes -> Mesh. Each stage is a function of plain data in its own folder; compile()
// only calls them in turn and refuses fabrics past the size limits before they are made.
// docs/architecture.md is the map.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "curves/curves.hpp"
#include "layout/layout.hpp"
#include "mesh/mesh.hpp"
#include "nurbs/nurbs.hpp"
#include "pattern.hpp"
#include "measure/crossings.hpp"
#include "relax/relax.hpp"
#include "sweep/sweep.hpp"
#include "tubes/tubes.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc {

using tubes::View;
using curves::CurvePiece;

// Mesh density: vertices around each ring, and the chord error of the surface along
// the yarn as a fraction of the yarn's diameter.
enum class Quality { draft, normal, fine };
struct Density {
  int sides;
  double chord_tolerance;
};
Density density(Quality quality);  // draft: 6, 5%; normal: 12, 1%; fine: 24, 0.25%

// The density a fabric needs seen whole in a full view of `width` x `height` pixels (a
// 1920 x 1080 screen; the fabric fits both ways, so a garment front taller than it is wide
// fits its height into the 1080): how many pixels a loop spans there picks it. A loop of 40
// pixels or more is drawn at normal quality, of 16 or more at 8 sides and 2.5%. Smaller,
// the chord error along the yarn is 2 / pixels of its diameter (5% to 50%: about half a
// pixel), and the ring has the fewest sides (at least 3) whose own chord error is no
// larger: a sweater front is not meshed at a swatch close-up's density. Below 16 pixels a
// loop's yarn is some 4 pixels across and its plies and fibres under a pixel, so the baked
// maps would show only their average: `maps` says whether they are worth drawing.
inline constexpr int view_width = 1920, view_height = 1080;
inline constexpr Density coarsest_view_density{3, 0.5};
struct ViewDensity {
  Density density;
  double loop_pixels;
  bool maps = true;
};
ViewDensity density_for_view(const layout::Layout& layout, int width = view_width, int height = view_height);
// The same rule for a loop `loop_pixels` across.
ViewDensity density_for_loop_pixels(double loop_pixels);

// Whether the repeat of a fabric relaxed by repeat is meshed once and placed many times
// (tiles/): automatic does it for a fabric whose plain mesh would pass flat_vertices (a
// plain .glb of some 50 MB, which a browser takes about a second to load; instanced, a
// sweater front is 3 MB and loads in a tenth of that).
enum class Instancing { automatic, flatten, instance };
inline constexpr std::uint64_t flat_vertices = 1'000'000;

struct CompileOptions {
  yarn_paths::LoopModel loop_model = yarn_paths::LoopModel::smooth;
  nurbs::Parametrisation parametrisation = nurbs::Parametrisation::chord_length;
  View view = View::surface;
  int sides = 12;                 // vertices per tube ring, >= 3 (plies get about half, at least 5)
  double chord_tolerance = 0.01;  // as a fraction of the yarn diameter, > 0
  // Contact relaxation after the layout (see relax/relax.hpp); off: the layout's curves as
  // they are. Programs default it by relaxed_by_default; here it is off, for the tests
  // and benchmarks that time or check the layout's geometry.
  bool relax = false;
  relax::Options relaxation;
  int threads = 0;                // 0: every core; the result is the same for any count
  // Sides and tolerance from the fabric's size in a full view (density_for_view) rather
  // than the two fields above: what the programs do unless a quality or either is given.
  bool density_from_view = false;
  // With density_from_view, a close-up this many pixels a loop (a picture of a few loops
  // across): the density is the finer of this view's and the full view's. 0: none.
  double close_up_loop_pixels = 0.0;
  Instancing instancing = Instancing::automatic;
  // Each yarn drawn as its plies' cores and its fibres and flyaways (fibres/fibres.hpp),
  // for close-ups, rather than as a tube; never instanced.
  bool fibres = false;
  // The tube's surface baked from the fibre model into normal, occlusion and colour maps
  // (fibres/bake.hpp) for a surface mesh of tubes; the programs turn it on unless
  // --textures off. Off here, for the tests that count a mesh's bytes.
  bool textures = false;
  // With density_from_view: the maps only where the view shows them (ViewDensity::maps);
  // what the programs do unless --textures is given.
  bool textures_from_view = false;
  // Called with a stage's name and how far it is, in [0, 1], from any thread (so it must
  // be thread-safe); for a progress display. It never changes the result.
  std::function<void(const char* stage, double fraction)> progress;
};

// What the stages made: each stage's own result, and nothing of how long they took
// (the caller times them through CompileOptions::progress).
struct Fabric {
  layout::Layout layout;
  std::vector<CurvePiece> pieces;  // the curves stage's
  mesh::Mesh mesh;                 // the tubes stage's
  bool relaxed = false;
  relax::Stats relaxation;         // when relaxed
  // Relaxed: how its knot diagram changed (measure::relaxation_changes), seen from the
  // face; work in the round unrolled into its flat frame (relax::tube_as_flat).
  bool crossings_checked = false;
  measure::CrossingChanges crossings;
  // Relaxed whole because, relaxed by repeat, a yarn passed through another.
  bool tiling_refused = false;
  // The density used, and why (from the view, or as given).
  Density density{12, 0.01};
  std::string density_choice;
  // Which mesh was made, and why: "flat" or "instanced", and the reason in words.
  bool instanced = false;
  std::string mesh_choice;
};

// Whether a relaxed fabric's yarn cores were left overlapping past the relaxation's own
// tolerance (`relaxation`: the options it was relaxed with): it stopped at its sweep limit
// without finding a fabric that could exist, which the program says.
inline bool cores_left_overlapping(const Fabric& fabric, const relax::Options& relaxation) {
  return fabric.relaxed && fabric.relaxation.end_overlap > relaxation.tolerance;
}

// Whether knitc relaxes a fabric unless told: the smooth model's, so that no two yarn
// cores overlap; the paper model stays the seed paper's unrelaxed geometry.
inline bool relaxed_by_default(yarn_paths::LoopModel model) { return model == yarn_paths::LoopModel::smooth; }

// Sizes past which compile() refuses a fabric rather than run out of memory (the
// limits, declared with the pattern).
inline constexpr std::uint64_t max_vertices = limits::mesh_vertices;
inline constexpr std::uint64_t max_loops = limits::fabric_loops;

// A pattern the compiler cannot make geometry for (yet). what() is "file:line: ...".
class CompileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The fewest vertices the pattern's mesh could have at `options`' density (or, from the
// view, the coarsest the view can choose), from its loop count alone, before it is laid
// out: compile() refuses a fabric past max_vertices by this at once.
double least_vertices(const Pattern& pattern, const CompileOptions& options);

// The pattern's knit graph. Throws CompileError at the row it cannot work (a dropped
// stitch whose wale cannot unravel): `knitc check` asks this too.
knit_graph::Graph knit(const Pattern& pattern);

// Compiles a validated pattern (the runtime validates) into geometry. Throws
// CompileError for a fabric past the size limits.
Fabric compile(const Pattern& pattern, const CompileOptions& options);
// The stages after the layout, on a given one (its loops' data points may be changed):
// yarn paths, curves, sweep, mesh.
Fabric compile(const Pattern& pattern, layout::Layout layout, const CompileOptions& options);

}  // namespace knitc
