// Preview images of a mesh: real OpenGL, drawn offscreen on the CPU through Mesa's OSMesa
// (llvmpipe), so it needs no GPU and no display.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace knitc::render {

struct RenderOptions {
  // Size of one view in pixels (1 to 16384 each). With Side::both the image is 2 * width wide.
  int width = 960, height = 720;
  // face: seen from +Z, the side toward the viewer in fabric coordinates, +X to the right.
  // back: the swatch flipped around its vertical (Y) axis, as a knitter turns it over: seen
  //   from -Z, +Y still up, so the +X edge appears on the left of the image.
  // both: face on the left half and back on the right half of one image of 2 * width.
  enum class Side { face, back, both } side = Side::face;
  // Anti-aliasing: samples per output pixel, taken on a k x k grid with k = ceil(sqrt(samples))
  // (so 1 = none, 4 = 2 x 2, 9 = 3 x 3, 16 = 4 x 4) and averaged in linear light.
  // Values below 1 count as 1; k is lowered if the supersampled frame would be too large.
  int samples = 4;
  // Background, linear RGB in [0, 1] like mesh::Material::base_color (0.7 is about #DADADA).
  glm::vec3 background{0.7f};
};

// Draws `mesh` and returns the bytes of a PNG file: 8-bit RGB, sRGB-encoded, rows top-down.
//
// The view is orthographic and frames the XY extent of the mesh's bounding box with a margin of
// about 4% of its larger side; face and back use the same framing, so the halves of `both`
// mirror each other. Triangles are lit per pixel by a key light (upper left, in front) and a
// fill light (right), both fixed to the camera, with smooth shading from the normals (flat
// shading where a primitive has none); a surface facing the viewer shows about its material's
// base colour, so the image matches the colours the pattern asked for. Lines and line strips are
// drawn unlit, about 1.5 output pixels wide, in their material's colour.
//
// The same mesh and options give the same bytes on the same machine and Mesa build. An empty mesh
// gives an image of only the background. Each call creates and destroys its own OSMesa context,
// so calls on different threads may run concurrently. Memory: the mesh is drawn from its own
// arrays (no copy); the frame takes about 20 bytes per supersampled pixel.
//
// Throws std::runtime_error when the options are out of range, the mesh is malformed (an index
// past its positions, a normals array of the wrong length, a material index that does not exist)
// or OpenGL fails (no OSMesa context, a shader that does not compile, out of memory).
std::string png(const mesh::Mesh& mesh, const RenderOptions& options = {});

}  // namespace knitc::render
