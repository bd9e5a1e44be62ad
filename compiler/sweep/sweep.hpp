// The sweep: samples along a centreline, a frame at each sample, and a cross-section
// swept along them into a closed tube. It knows curves and cross-sections, not stitches.
#pragma once

#include <limits>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"
#include "nurbs/nurbs.hpp"

namespace knitc::sweep {

// Parameters in [u0, u1], first u0 and last u1, spaced so that the chords between
// consecutive samples of the tube's outer surface (radius `radius` around the curve)
// stay within `chord_tolerance` of the surface: a centreline arc of curvature k and
// length L has sagitta (1/k + r) (1 - cos(k L / 2)) ~ (1 + r k) k L^2 / 8 on the outer
// fibre; and no two samples further apart than `max_step` along the curve (for twisted
// plies, whose helices need samples where the centreline is straight). Samples are
// equidistributed in that density. chord_tolerance > 0, radius >= 0, max_step > 0.
std::vector<double> sample_parameters(const nurbs::Curve& curve, double u0, double u1,
                                      double chord_tolerance, double radius,
                                      double max_step = std::numeric_limits<double>::infinity());

// About how many samples sample_parameters would place along a curve through `points`
// (a piece's data points), from their polygon alone: for refusing a mesh too large to
// make before fitting its curves. Within about 20% of the count on knitc's fabrics.
double estimate_samples(std::span<const glm::dvec3> points, double tolerance, double radius,
                        double max_step = std::numeric_limits<double>::infinity());

enum class FrameKind {
  frenet,               // tangent, principal normal, binormal: the seed paper's choice
  rotation_minimising,  // double reflection (Wang, Juttler, Zheng, Liu 2008)
};

// An orthonormal frame per sample: tangent t, normal n, binormal b = t x n.
struct Frames {
  std::vector<glm::dvec3> origin, tangent, normal, binormal;
  std::size_t size() const { return origin.size(); }
};

// Frames at the given parameters (at least two). Frenet frames fall back to the previous
// normal, projected, where the curvature vanishes. The curve is evaluated on up to
// `threads` threads (0: every core), the rotation-minimising frames then propagated in
// order: the same frames for any count.
Frames frames(const nurbs::Curve& curve, std::span<const double> u, FrameKind kind, int threads = 1);

// Given origins, unit tangents and the first normal, fills the other normals by double
// reflection and every binormal: the rotation-minimising frame of a polyline.
void propagate_rotation_minimising(Frames& frames);

// A yarn's cross-section, swept along its centreline.
struct CrossSection {
  enum class Shape { circle, ellipse, plied } shape = Shape::circle;
  double radius = 0.5;  // half the yarn's width, mm
  // ellipse: minor / major; the same area as the circle of `radius`, the minor axis kept
  // as close to `flat_normal` as the tangent allows (a yarn pressed flat in the fabric).
  double aspect = 1.0;
  glm::dvec3 flat_normal{0.0, 0.0, 1.0};
  // plied: `plies` round plies, touching, the bundle `radius` wide, each turning about
  // the centreline `twist` times per mm of yarn, in the rotation-minimising frame;
  // positive is a Z (right-handed) twist, negative S.
  int plies = 1;
  double twist = 0.0;
};

// One tube of a cross-section: its own frames and ring half-axes (along normal, binormal).
struct Strand {
  Frames frames;
  double along_normal = 0.5, along_binormal = 0.5;
  std::vector<glm::dvec2> axes;  // per frame, over the two above (empty: those): along normal, binormal
};

// The strands of a cross-section along the frames: one for a circle or an ellipse, one
// per ply. `arc_length` holds the yarn's length in mm at each frame. `pressed`, per frame
// or empty: the direction the yarn is pressed from, across it, of length 1 - aspect (< 1);
// there a circle flattens to an ellipse of its area whose minor axis lies along it, the
// axis kept where the yarn is not pressed (relax/press.hpp); a plied section's plies, each
// kept round, have their centres moved onto that ellipse. An ellipse keeps its own shape.
std::vector<Strand> strands(const Frames& frames, std::span<const double> arc_length, const CrossSection& section,
                            std::span<const glm::dvec3> pressed = {});

// Appends each strand as a closed tube to a triangle primitive: rings of `sides` vertices
// (plus a seam vertex repeating the first, for the texture's v = 1), quads between rings,
// a flat cap at each end. Triangles wind counter-clockwise seen from outside; normals point
// out. TEXCOORD u is the yarn's length in mm (`arc_length`), v runs around the section in
// [0, 1]. The seam and cap rim vertices repeat their ring's positions exactly, so welding
// by position closes each surface.
void append_tubes(std::span<const Strand> strands, std::span<const double> arc_length, int sides, mesh::Primitive& out);

// The vertices and indices append_tubes adds for `strands` strands of `rings` rings.
struct TubeSize {
  std::size_t vertices, indices;
};
TubeSize tube_size(std::size_t rings, int sides, std::size_t strands);

// As append_tubes, into arrays already sized: vertices from `vertex_offset`, indices from
// `index_offset` (indices count from the primitive's start). Disjoint ranges may be
// written from different threads.
void write_tubes(std::span<const Strand> strands, std::span<const double> arc_length, int sides, mesh::Primitive& out,
                 std::size_t vertex_offset, std::size_t index_offset);

// A stretch of one strand, its rings `first` to `last` (inclusive, last > first), for
// meshes cut at chosen rings and joined there to another stretch (an instanced tile and
// the fabric round it): ring i's vertex k sits at angle 2 pi k / sides + phase[i - first]
// round the section (so a cut's seam is put where both sides of it agree), u is
// `u[i - first]`, and a cap closes an end only where asked (a cut is open). `offset` is
// subtracted from every position (a tile's own origin).
struct Stretch {
  std::size_t first = 0, last = 0;
  bool cap_start = true, cap_end = true;
};
TubeSize stretch_size(const Stretch& stretch, int sides);
void write_stretch(const Strand& strand, const Stretch& stretch, std::span<const double> u, std::span<const double> phase,
                   const glm::dvec3& offset, int sides, mesh::Primitive& out, std::size_t vertex_offset, std::size_t index_offset);

// The angle round strand ring i, in its (normal, binormal) plane, of the direction a cut's
// seam is put at: the fabric's +Z made square to the tangent (+X where the tangent runs
// along Z). Both sides of a cut get the same point of the same section from it.
double seam_angle(const Strand& strand, std::size_t i);

// Appends the strands' rings and long edges as a LINES primitive, like the seed paper's
// wireframe figure.
void append_wireframe(std::span<const Strand> strands, int sides, mesh::Primitive& out);

}  // namespace knitc::sweep
