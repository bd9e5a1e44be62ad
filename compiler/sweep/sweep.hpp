// The sweep: samples along a centreline, a frame at each sample, and a cross-section
// swept along them into a closed tube. It knows curves and cross-sections, not stitches.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"
#include "nurbs/nurbs.hpp"

namespace knitc::sweep {

// Parameters in [u0, u1], first u0 and last u1, spaced so that the chords between
// consecutive samples of the tube's outer surface (radius `radius` around the curve)
// stay within `chord_tolerance` of the surface: a centreline arc of curvature k and
// length L has sagitta (1/k + r) (1 - cos(k L / 2)) ~ (1 + r k) k L^2 / 8 on the outer
// fibre. Samples are equidistributed in that density. chord_tolerance > 0, radius >= 0.
std::vector<double> sample_parameters(const nurbs::Curve& curve, double u0, double u1,
                                      double chord_tolerance, double radius);

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
// normal, projected, where the curvature vanishes.
Frames frames(const nurbs::Curve& curve, std::span<const double> u, FrameKind kind);

// Appends a closed tube to a triangle primitive: a circle of `radius` with `sides`
// vertices per ring (sides >= 3) at each frame, quads between rings, and a flat cap at
// each end. Triangles wind counter-clockwise seen from outside; normals point out. The
// cap's rim vertices repeat the end rings' positions exactly, so welding by position
// closes the surface.
void append_tube(const Frames& frames, double radius, int sides, mesh::Primitive& out);

// Appends the tube's rings and long edges as a LINES primitive, like the seed paper's
// wireframe figure.
void append_wireframe(const Frames& frames, double radius, int sides, mesh::Primitive& out);

}  // namespace knitc::sweep
