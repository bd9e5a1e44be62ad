// Relaxation: moves the laid-out yarns to the shape a real yarn takes in the fabric: its
// cores never overlap, its shells compress where yarns press on each other, its bending
// stiffness opens the loops, it keeps its length and passes every other yarn on the side
// it did. docs/relaxation.md tells what it achieves and what not yet.
//
// A yarn has a compact core and a free (visible) diameter (yarn/size.hpp). The yarns are
// chains of centreline points (the layout's curves, refined so that consecutive points
// are about 0.7 core diameters apart) and the chains' segments are capsules. Position-based
// dynamics (Muller et al. 2007), in a fixed order so the result is the same on any machine
// and for any thread count:
//   - contact: two segments of different pieces, or of one piece more than 1.8 free
//     diameters apart along it, end at least their core radii apart (plus an 8% skin, so
//     the smooth curve through the chain clears too), reached over the first sweeps (a
//     ramp); between the cores' and the free radii the shells push back by a pressure law,
//     (h0 / h)^p - 1 of the shells' thickness h (Singal et al.); where two cross seen from
//     the face, the one in front stays in front (flat work);
//   - length: every segment keeps its length;
//   - bending: an elastic rod whose rest shape is straight: every three points a step
//     toward their chord, keeping their centroid; no bend tighter than 1.2 free radii;
//   - size: the swatch's change of width and height, sped up; a periodic repeat's from
//     the strain its constraints ask for (see relax.cpp).
// The contacts are found with a grid of cells about two diameters wide, rebuilt when some
// point has moved a quarter diameter: each sweep's time and memory grow linearly with the
// fabric, and the sweeps hardly grow with it (docs/relaxation.md).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "layout/layout.hpp"
#include "yarn/size.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc::relax {

enum class Boundary {
  free,      // a swatch: every edge free to move
  held,      // the cast-on and the last course held where the layout put them
  periodic,  // one repeat of a fabric endless across and up (flat work): contacts wrap from
             // one selvedge to the other, one loop width per wale, and from the last course to
             // the cast-on, one course spacing per course; the turns and tails take no part
};

struct Options {
  Boundary boundary = Boundary::free;
  double spacing = 0.7;     // chain points about this many core diameters apart (see refine)
  double tolerance = 0.02;  // done when no two cores overlap by more than this fraction of the core d
  int max_iterations = 400;
  double settled_motion = 0.002;  // done once the loops' free points moved this many core d in a sweep, on average
  int threads = 0;          // 0: every core; the result is the same for any count
  // Free edges on flat work with a repeat (repeat.hpp): relax the repeat alone, periodic,
  // tile it across the fabric, then relax the edges and what does not repeat against it.
  bool by_repeat = true;
  // By repeat, where the edges' bands form a frame round the held interior: each band
  // relaxed as one period of a strip periodic along its edge and copied along it, only the
  // corners relaxed against the copies (strips.hpp); off: the bands relaxed whole.
  bool by_strips = true;
  // The sections pressed at the end (press.hpp); off, the caller presses them (the
  // compiler, beside the crossings check, which reads only the points).
  bool pressed = true;
};

// The constants of the method, in diameters or radii.
inline constexpr double contact_skin = 0.08;         // cores are pushed to (1 + skin) (r_a + r_b) apart
inline constexpr double contact_margin = 0.25;       // contact pairs are listed up to this many free d past the free radii
inline constexpr double shell_exponent = 2.6;        // p of the pressure law: 2.4 (acrylic) to 2.9 (cotton), Singal et al.
inline constexpr double shell_rate = 0.02;           // a shell's push a sweep, of its thickness, per unit of pressure
inline constexpr double bending_stiffness = 0.3;     // of the way to straight, every three points a sweep
inline constexpr double tightest_bend_radii = 1.2;   // no chain bends tighter than this many free radii
inline constexpr double size_gain = 1024.0;          // the size boost per loop across (see relax.cpp)
// The lengths are taken back this many times a sweep after bending: bending stretches the
// yarn round the contacts by more than one pass returns, and with one pass the library's
// whole-relaxed fabrics stopped at the sweep limit 2 to 3% long (three: 0.0 to 1.2%, in
// fewer sweeps; docs/relaxation.md).
inline constexpr int length_passes = 3;
inline constexpr int ramp_sweeps = 10;               // the contact distance reaches the radii over this many sweeps
// and then the shells grow from the cores to the free radii over as many again: switched
// on whole, every pressed pair was pushed out to its free surfaces in one sweep, and the
// 3x3 cable panel passed 25 of its 2,500 crossings through in that sweep (12 in all so, 43 before).
inline constexpr double settled_pushes = 3.0;        // done once no push is deeper than this many tolerances
inline constexpr double settled_length = 0.015;      // and no piece's length is further than this fraction off
                                                     // (and the loops moved by Options::settled_motion)

struct Stats {
  int iterations = 0;
  double start_overlap = 0.0;  // deepest overlap of two cores before, as a fraction of the thickest core d
  double end_overlap = 0.0;    // and after
  double compression = 0.0;    // after: the mean squeeze of the pressed shells, 1 - h / h0 (0: none pressed)
  double length_change = 0.0;  // the largest relative change of a piece's length, >= 0
  glm::dvec2 period{0.0};      // mm, a periodic swatch's repeat at the end (0: not periodic that way)
  // Relaxed by repeat: the tile's loops across and up (0: the whole fabric at once), the
  // tile's sweeps (the others are the edges'), and the share of the yarn's points held as
  // tiled.
  int repeat_wales = 0, repeat_courses = 0, repeat_iterations = 0;
  int repeat_wale0 = 0, repeat_course0 = 0;  // the tile's first loop in the fabric
  double held_share = 0.0;
  // Of the edges: the bands relaxed as strips periodic along them (0 to 4), the most
  // sweeps one took, and the share of the yarn's points they placed (the rest of the
  // edges, the corners, took `iterations`).
  int strips = 0, strip_iterations = 0;
  double strip_share = 0.0;
  // The sweeps over which the edges' relaxation carried the yarn to the tile's places
  // (Start::from), where jumping there would have left it too deep (0: jumped).
  int morph_sweeps = 0;
};

struct Relaxed {
  std::vector<yarn_paths::Piece> pieces;
  Stats stats;
  // Relaxed by repeat: per point (the pieces' points in order) the point whose
  // surroundings are this one's moved by a whole number of tiles (a point of the held
  // interior far from anything the edges' relaxation moved: one of its tile point's
  // copies; or an edge strip's copy far from the corners: one of its strip point's), or
  // its own index; empty when relaxed whole. What depends only on a point's surroundings
  // (pressing) is found once per tile or strip point.
  std::vector<std::uint32_t> same_as;
};

// `same_as` (Relaxed's) per piece of `pieces`, in the piece's own indices: a point whose
// first copy lies in another piece is its own. Empty when same_as is.
std::vector<std::vector<std::uint32_t>> same_as_by_piece(const std::vector<yarn_paths::Piece>& pieces,
                                                         const std::vector<std::uint32_t>& same_as);

// Work in the round as flat work, for the crossings check (measure::relaxation_changes
// looks along -z at the face): `laid` (relax::refine's chains) and `relaxed` (the same
// points moved) unrolled into the layout's flat frame, z out of the tube, each piece cut
// where its yarn passes from one round into the next (there the unrolled yarn jumps back a
// round's width), both at the same points. The points stay in order, so a Relaxed's
// same_as still holds. The pieces carry their points and yarn only.
struct TubeAsFlat {
  std::vector<yarn_paths::Piece> laid, relaxed;
};
TubeAsFlat tube_as_flat(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& laid,
                        const std::vector<yarn_paths::Piece>& relaxed);

// The pieces with points inserted on each piece's interpolating curve (chord-length
// parametrisation) so that no two consecutive points are more than spacing x d apart;
// the old points are kept and loop_first follows them. diameter: mm, per Pattern::yarns
// (the relaxation passes the core diameters). On up to `threads` threads (0: every
// core); the same points for any count.
std::vector<yarn_paths::Piece> refine(std::vector<yarn_paths::Piece> pieces, const std::vector<double>& diameter,
                                      double spacing, int threads = 1);

// Relaxes refined chains (see refine) laid out by `layout`; the result has the same points,
// moved. sizes: per Pattern::yarns.
Relaxed relax(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains, const std::vector<yarn::Size>& sizes,
              const Options& options);

}  // namespace knitc::relax
