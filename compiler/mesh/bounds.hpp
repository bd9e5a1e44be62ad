// The box a mesh or one primitive spans: one rule for the writers, the statistics and
// the preview's camera. Header only, like the mesh.
#pragma once

#include <cmath>

#include <glm/common.hpp>

#include "mesh/mesh.hpp"

namespace knitc::mesh {

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};  // mm
  bool empty = true;               // no finite position
  void add(const glm::vec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return;
    if (empty) {
      min = max = v;
      empty = false;
    } else {
      min = glm::min(min, v);
      max = glm::max(max, v);
    }
  }
};

inline Bounds bounds(const Primitive& p) {
  Bounds b;
  for (const auto& v : p.positions) b.add(v);
  return b;
}

// The fabric's box: the plain primitives and every placed instance.
inline Bounds bounds(const Mesh& mesh) {
  Bounds b;
  for (const auto& p : mesh.primitives)
    for (const auto& v : p.positions) b.add(v);
  for (const auto& group : mesh.instanced) {
    Bounds tile;
    for (const auto& p : group.primitives)
      for (const auto& v : p.positions) tile.add(v);
    if (tile.empty) continue;
    for (const auto& t : group.translations) {
      b.add(tile.min + t);
      b.add(tile.max + t);
    }
  }
  return b;
}

}  // namespace knitc::mesh
