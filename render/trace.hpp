// A preview lit like a photograph: rays traced against the mesh with Embree on the CPU,
// with soft shadows from an area light, ambient occlusion from the sky, the sheen of
// fibres, a perspective camera and many samples a pixel.
#pragma once

#include <cstdint>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/bounds.hpp"
#include "mesh/mesh.hpp"
#include "render.hpp"

namespace knitc::render {

struct TraceOptions {
  int width = 960, height = 720;  // one view, 1 to 16384 pixels a side; `both` is twice as wide
  using Side = RenderOptions::Side;
  Side side = Side::face;
  // Samples a pixel (1 to 1024), stratified on a grid: antialiasing, and each sample's
  // shadow and sky rays average into soft shadows and occlusion.
  int samples = 16;
  std::uint64_t seed = 1;  // the samples' jitter: the same seed, the same image
  int threads = 0;         // 0: every core; the image is the same for any count
  // The whole fabric in view (0), or a close-up: a square this many mm across at the
  // fabric's middle fills the picture's shorter side.
  double close_up = 0.0;
  glm::vec3 background{0.7f};  // linear RGB
};

// Draws the triangles of `mesh`, and its lines whose line_radius is > 0 as round fibres of
// that radius (other lines are not drawn: the rasterised preview draws wireframes), and returns the bytes of an 8-bit sRGB PNG.
//
// Camera: perspective (a 20-degree view), square to the fabric from its face (+Z) or its
// back (-Z, turned about +Y as a knitter turns it), far enough that the fabric's XY extent
// (or the close-up square) fits with a margin. Light, all in linear RGB and fixed to the
// camera: a disc-shaped key light up and to the left in front (soft shadows from one shadow
// ray a sample towards a point on the disc) and a uniform sky over every direction a surface
// faces (ambient occlusion from one cosine-weighted ray a sample). A surface square to the
// camera in open light shows about its base colour times its vertex colour; the material's
// sheen colour adds a rim towards grazing angles. Normals are the mesh's, interpolated, and
// turned toward the viewer (winding is not part of the mesh's contract).
//
// The same mesh, options and seed give the same bytes for any thread count: every sample's
// random numbers come from a hash of (seed, pixel, sample), and the pixels are independent.
// Memory: Embree's copy of the triangles and its BVH (about 100 bytes a triangle), and the
// image. Throws std::runtime_error for options out of range, a malformed mesh, or an Embree
// failure.
std::string traced_png(const mesh::Mesh& mesh, const TraceOptions& options = {});

// Where `point` (mm) lands in the traced picture of a mesh whose bounds are `box`: pixel
// coordinates (x right, y down, from the view's top-left corner; add width for the back
// half of `both`), or a point behind the camera as (-1, -1).
glm::vec2 traced_pixel(const mesh::Bounds& box, const TraceOptions& options, bool from_back, glm::vec3 point);

}  // namespace knitc::render
