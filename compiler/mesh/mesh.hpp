// The mesh: flat arrays ready for the writers. Positions in millimetres in fabric
// coordinates (the writers convert units); normals of unit length.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace knitc::mesh {

enum class Mode { triangles, lines, line_strip };

// A texture's pixels, 8 bits a channel, rows from the top (texture coordinate t = 0) down.
struct Image {
  int width = 0, height = 0, channels = 0;  // channels: 1 (grey) or 3 (RGB)
  std::vector<unsigned char> pixels;         // width * height * channels
};

// A material's maps (indices into Mesh::images, -1: none), read through the primitive's
// TEXCOORD_0 scaled by 1 / repeat (glTF's KHR_texture_transform): a tile `repeat.x` mm of
// yarn long and `repeat.y` turns round it, repeated. The normal map is in the tangent
// space glTF's TANGENT gives (mesh/tangents.hpp): red along +u, green along +v.
struct Textures {
  int normal = -1;     // RGB: the unit normal, (n + 1) / 2
  int occlusion = -1;  // grey: the share of the sky a point sees, 1 open
  int colour = -1;     // RGB, sRGB-encoded: multiplies the base colour
  glm::vec2 repeat{1.0f};
  bool any() const { return normal >= 0 || occlusion >= 0 || colour >= 0; }
};

struct Material {
  std::string name;
  glm::vec3 base_color{1.0f};  // linear RGB in [0, 1]
  glm::vec3 sheen_color{0.0f}; // linear RGB: the soft rim light of fibres (KHR_materials_sheen)
  float sheen_roughness = 0.5f;
  Textures textures{};
};

struct Primitive {
  int material = 0;                 // index into Mesh::materials
  Mode mode = Mode::triangles;
  std::vector<glm::vec3> positions; // mm
  std::vector<glm::vec3> normals;   // empty, or one per position
  std::vector<glm::vec2> uvs;       // empty, or one per position: u in mm along the yarn, v around it in [0, 1]
  // Empty, or one per position: linear RGB in [0, 1] that multiplies the material's base
  // colour (glTF's COLOR_0): a yarn dyed along its length.
  std::vector<glm::vec3> colors;
  // Lines only: the radius (mm) of the round fibre each segment stands for, > 0 for a yarn's
  // fibres (the traced preview draws them as such); 0 draws a line of a pixel or two.
  float line_radius = 0.0f;
  std::vector<std::uint32_t> indices;
};

// One mesh drawn many times (glTF's EXT_mesh_gpu_instancing): its primitives in their own
// frame, and the translation (mm) that places each copy in the fabric.
struct Instances {
  std::vector<Primitive> primitives;
  std::vector<glm::vec3> translations;
};

struct Mesh {
  std::vector<Material> materials;
  std::vector<Image> images;  // the materials' maps
  std::vector<Primitive> primitives;
  std::vector<Instances> instanced;  // empty: every triangle is in `primitives`
};

}  // namespace knitc::mesh
