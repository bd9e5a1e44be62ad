// The mesh: flat arrays ready for the writers. Positions in millimetres in fabric
// coordinates (the writers convert units); normals of unit length.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace knitc::mesh {

enum class Mode { triangles, lines, line_strip };

struct Material {
  std::string name;
  glm::vec3 base_color{1.0f};  // linear RGB in [0, 1]
};

struct Primitive {
  int material = 0;                 // index into Mesh::materials
  Mode mode = Mode::triangles;
  std::vector<glm::vec3> positions; // mm
  std::vector<glm::vec3> normals;   // empty, or one per position
  std::vector<std::uint32_t> indices;
};

struct Mesh {
  std::vector<Material> materials;
  std::vector<Primitive> primitives;
};

}  // namespace knitc::mesh
