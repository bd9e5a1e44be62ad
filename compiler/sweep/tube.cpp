#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "sweep/sweep.hpp"

namespace knitc::sweep {

namespace {

// Ring vertices: position and outward direction for each side at each frame.
void append_rings(const Frames& f, double radius, int sides, mesh::Primitive& out, bool with_normals) {
  std::vector<double> cosines(sides), sines(sides);
  for (int k = 0; k < sides; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / sides;
    cosines[k] = std::cos(theta);
    sines[k] = std::sin(theta);
  }
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (int k = 0; k < sides; ++k) {
      const glm::dvec3 dir = cosines[k] * f.normal[i] + sines[k] * f.binormal[i];
      out.positions.emplace_back(f.origin[i] + radius * dir);
      if (with_normals) out.normals.emplace_back(glm::normalize(glm::vec3(dir)));
    }
  }
}

// A flat cap: a centre vertex and a copy of the ring's rim with the cap's normal.
void append_cap(const Frames& f, std::size_t ring, std::uint32_t ring_first, int sides, bool at_start,
                mesh::Primitive& out) {
  const glm::vec3 normal(at_start ? -f.tangent[ring] : f.tangent[ring]);
  const auto centre = static_cast<std::uint32_t>(out.positions.size());
  out.positions.emplace_back(f.origin[ring]);
  out.normals.push_back(normal);
  for (int k = 0; k < sides; ++k) {
    const glm::vec3 rim = out.positions[ring_first + k];  // a copy: push_back may reallocate
    out.positions.push_back(rim);
    out.normals.push_back(normal);
  }
  for (int k = 0; k < sides; ++k) {
    const std::uint32_t a = centre + 1 + k, b = centre + 1 + (k + 1) % sides;
    // Counter-clockwise seen from outside: from -t at the start, from +t at the end.
    if (at_start) out.indices.insert(out.indices.end(), {centre, b, a});
    else out.indices.insert(out.indices.end(), {centre, a, b});
  }
}

}  // namespace

void append_tube(const Frames& f, double radius, int sides, mesh::Primitive& out) {
  assert(f.size() >= 2 && sides >= 3 && out.mode == mesh::Mode::triangles);
  const auto base = static_cast<std::uint32_t>(out.positions.size());
  const auto rings = f.size();
  out.positions.reserve(out.positions.size() + rings * sides + 2 * (sides + 1));
  out.normals.reserve(out.positions.capacity());
  append_rings(f, radius, sides, out, true);
  out.indices.reserve(out.indices.size() + (rings - 1) * sides * 6 + 2 * sides * 3);
  for (std::size_t i = 0; i + 1 < rings; ++i) {
    const auto row = base + static_cast<std::uint32_t>(i * sides);
    for (int k = 0; k < sides; ++k) {
      // (i, k), (i, k+1), (i+1, k), (i+1, k+1): the side direction crossed with the
      // tangent points outward.
      const std::uint32_t a = row + k, b = row + (k + 1) % sides;
      const std::uint32_t c = a + sides, d = b + sides;
      out.indices.insert(out.indices.end(), {a, b, c, b, d, c});
    }
  }
  append_cap(f, 0, base, sides, true, out);
  append_cap(f, rings - 1, base + static_cast<std::uint32_t>((rings - 1) * sides), sides, false, out);
}

void append_wireframe(const Frames& f, double radius, int sides, mesh::Primitive& out) {
  assert(f.size() >= 2 && sides >= 3 && out.mode == mesh::Mode::lines);
  const auto base = static_cast<std::uint32_t>(out.positions.size());
  append_rings(f, radius, sides, out, false);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const auto row = base + static_cast<std::uint32_t>(i * sides);
    for (int k = 0; k < sides; ++k) {
      const std::uint32_t a = row + k;
      out.indices.insert(out.indices.end(), {a, row + (k + 1) % sides});  // around the ring
      if (i + 1 < f.size()) out.indices.insert(out.indices.end(), {a, a + sides});  // along
    }
  }
}

}  // namespace knitc::sweep
