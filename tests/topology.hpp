// Mesh topology for the tests: welds vertices at equal positions and counts the edges
// that are not shared by exactly two triangles, so closed, two-manifold tubes can be told.
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace knitc::test {

struct TopologyReport {
  std::size_t welded_vertices = 0, edges = 0, triangles = 0;
  std::size_t non_manifold_edges = 0;    // used by other than exactly two triangles
  std::size_t inconsistent_edges = 0;    // the same directed edge twice
  double signed_volume = 0.0;            // mm^3, positive when triangles face out
  double least_component_volume = 0.0;   // the smallest of the components' signed volumes
  std::size_t components = 0;
};

// Welds vertices with identical positions, then checks the edges.
inline TopologyReport topology(const mesh::Primitive& prim) {
  std::map<std::tuple<float, float, float>, std::uint32_t> ids;
  std::vector<std::uint32_t> weld(prim.positions.size());
  for (std::size_t i = 0; i < prim.positions.size(); ++i) {
    const auto& p = prim.positions[i];
    weld[i] = ids.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<std::uint32_t>(ids.size())).first->second;
  }
  TopologyReport r;
  r.welded_vertices = ids.size();
  r.triangles = prim.indices.size() / 3;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  std::vector<std::uint32_t> parent(ids.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t t = 0; t < prim.indices.size(); t += 3) {
    const std::uint32_t v[3] = {weld[prim.indices[t]], weld[prim.indices[t + 1]], weld[prim.indices[t + 2]]};
    for (int e = 0; e < 3; ++e) {
      ++directed[{v[e], v[(e + 1) % 3]}];
      parent[find(v[e])] = find(v[(e + 1) % 3]);
    }
    const glm::dvec3 a(prim.positions[prim.indices[t]]), b(prim.positions[prim.indices[t + 1]]),
        c(prim.positions[prim.indices[t + 2]]);
    r.signed_volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> undirected;
  for (const auto& [e, n] : directed) {
    if (n > 1) ++r.inconsistent_edges;
    undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}] += n;
  }
  r.edges = undirected.size();
  for (const auto& [e, n] : undirected) {
    if (n != 2) ++r.non_manifold_edges;
  }
  for (std::uint32_t i = 0; i < parent.size(); ++i) r.components += find(i) == i;
  std::map<std::uint32_t, double> volume;  // by component
  for (std::size_t t = 0; t < prim.indices.size(); t += 3) {
    const glm::dvec3 a(prim.positions[prim.indices[t]]), b(prim.positions[prim.indices[t + 1]]),
        c(prim.positions[prim.indices[t + 2]]);
    volume[find(weld[prim.indices[t]])] += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  r.least_component_volume = volume.empty() ? 0.0 : volume.begin()->second;
  for (const auto& [root, v] : volume) r.least_component_volume = std::min(r.least_component_volume, v);
  return r;
}

}  // namespace knitc::test
