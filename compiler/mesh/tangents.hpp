// Tangents for normal maps: the one rule for which way a map's red and green point on the
// surface. Red along +u of TEXCOORD_0 (along the yarn), green along +v (round it): glTF's
// TANGENT is (T, w) with T along +u, perpendicular to the normal, and w the sign that
// makes cross(normal, T) * w point along +v. The glTF writer writes it; the tracer uses it.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "mesh/mesh.hpp"

namespace knitc::mesh {

// A triangle's directions of +u and +v on its plane (unnormalised, weighted by its area,
// so sums over a vertex's triangles favour the large ones); zero for a triangle whose
// texture coordinates have no area.
struct UvDirections {
  glm::vec3 u{0.0f}, v{0.0f};
};

inline UvDirections uv_directions(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec2& t0,
                                  const glm::vec2& t1, const glm::vec2& t2) {
  const glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::vec2 d1 = t1 - t0, d2 = t2 - t0;
  const float r = d1.x * d2.y - d2.x * d1.y;
  if (!(std::abs(r) > 0.0f)) return {};
  const float sign = r > 0.0f ? 1.0f : -1.0f;
  return {sign * (e1 * d2.y - e2 * d1.y), sign * (e2 * d1.x - e1 * d2.x)};
}

// The tangent at a point of normal `n` (unit) whose surface runs along d.u and d.v there.
// Where the texture coordinates give no direction (a tube's flat cap), any direction
// perpendicular to n, with w = 1.
inline glm::vec4 tangent(const glm::vec3& n, const UvDirections& d) {
  glm::vec3 t = d.u - n * glm::dot(n, d.u);
  const float length = glm::length(t);
  if (!(length > 1e-12f)) {
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return {glm::normalize(glm::cross(n, a)), 1.0f};
  }
  t /= length;
  return {t, glm::dot(glm::cross(n, t), d.v) < 0.0f ? -1.0f : 1.0f};
}

// One tangent per vertex of a triangle primitive with normals and uvs: its triangles'
// directions summed, then made perpendicular to the vertex's normal.
inline std::vector<glm::vec4> vertex_tangents(const Primitive& p) {
  std::vector<UvDirections> sum(p.positions.size());
  for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
    const std::uint32_t a = p.indices[i], b = p.indices[i + 1], c = p.indices[i + 2];
    const UvDirections d = uv_directions(p.positions[a], p.positions[b], p.positions[c], p.uvs[a], p.uvs[b], p.uvs[c]);
    for (const std::uint32_t k : {a, b, c}) sum[k].u += d.u, sum[k].v += d.v;
  }
  std::vector<glm::vec4> out(p.positions.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = tangent(p.normals[k], sum[k]);
  return out;
}

}  // namespace knitc::mesh
