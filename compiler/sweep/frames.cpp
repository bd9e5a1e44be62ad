#include <cassert>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "parallel.hpp"
#include "sweep/sweep.hpp"

namespace knitc::sweep {

namespace {

using glm::dvec3;

// A unit vector perpendicular to unit t, from the world axis least aligned with it.
dvec3 any_perpendicular(const dvec3& t) {
  const dvec3 a = std::abs(t.x) <= std::abs(t.y) && std::abs(t.x) <= std::abs(t.z) ? dvec3(1, 0, 0)
                  : std::abs(t.y) <= std::abs(t.z)                                  ? dvec3(0, 1, 0)
                                                                                    : dvec3(0, 0, 1);
  return glm::normalize(a - glm::dot(a, t) * t);
}

// The principal normal where it is defined, else `fallback` made perpendicular to t.
dvec3 principal_normal(const dvec3& d1, const dvec3& d2, const dvec3& t, const dvec3& fallback) {
  const dvec3 b = glm::cross(d1, d2);
  const double speed = glm::length(d1);
  if (glm::length(b) > 1e-9 * speed * speed * speed) {
    return glm::normalize(glm::cross(b, t));  // N = B x T
  }
  const dvec3 n = fallback - glm::dot(fallback, t) * t;
  return glm::length(n) > 1e-12 ? glm::normalize(n) : any_perpendicular(t);
}

}  // namespace

void propagate_rotation_minimising(Frames& f) {
  for (std::size_t i = 0; i + 1 < f.size(); ++i) {
    // Reflect the frame in the plane bisecting the chord, then in the plane that takes
    // the reflected tangent onto the next tangent.
    const dvec3 v1 = f.origin[i + 1] - f.origin[i];
    const double c1 = glm::dot(v1, v1);
    dvec3 r = f.normal[i], t = f.tangent[i];
    if (c1 > 0.0) {
      r -= (2.0 / c1) * glm::dot(v1, r) * v1;
      t -= (2.0 / c1) * glm::dot(v1, t) * v1;
    }
    const dvec3 v2 = f.tangent[i + 1] - t;
    const double c2 = glm::dot(v2, v2);
    if (c2 > 0.0) r -= (2.0 / c2) * glm::dot(v2, r) * v2;
    // Remove rounding drift so the frame stays orthonormal over long yarns.
    const dvec3& tn = f.tangent[i + 1];
    f.normal[i + 1] = glm::normalize(r - glm::dot(r, tn) * tn);
  }
  for (std::size_t i = 0; i < f.size(); ++i) f.binormal[i] = glm::cross(f.tangent[i], f.normal[i]);
}

Frames frames(const nurbs::Curve& curve, std::span<const double> u, FrameKind kind, int threads) {
  assert(u.size() >= 2);
  const std::size_t count = u.size();
  Frames f;
  f.origin.resize(count);
  f.tangent.resize(count);
  f.normal.resize(count);
  f.binormal.resize(count);
  if (kind == FrameKind::rotation_minimising) {
    // Points and tangents need only the curve: evaluated in parallel, by blocks of
    // samples, each walking its knot spans (the samples ascend).
    constexpr std::size_t block = 1024;
    parallel_for((count + block - 1) / block, thread_count(threads), [&](std::size_t b) {
      std::optional<nurbs::Span> span;
      for (std::size_t i = b * block; i < std::min(count, (b + 1) * block); ++i) {
        if (!span || !span->holds(u[i]))
          span.emplace(curve, span ? nurbs::next_span(curve, span->index(), u[i]) : nurbs::find_span(curve, u[i]));
        const auto d = span->derivatives(u[i], 1);
        f.origin[i] = d[0];
        f.tangent[i] = glm::normalize(d[1]);
      }
    });
  }
  for (std::size_t i = 0; i < count && kind == FrameKind::frenet; ++i) {
    const auto d = nurbs::derivatives(curve, u[i], 2);
    f.origin[i] = d[0];
    f.tangent[i] = glm::normalize(d[1]);
    const dvec3 previous = i > 0 ? f.normal[i - 1] : any_perpendicular(f.tangent[i]);
    f.normal[i] = principal_normal(d[1], d[2], f.tangent[i], previous);
  }
  if (kind == FrameKind::rotation_minimising) {
    const auto d = nurbs::derivatives(curve, u[0], 2);
    f.normal[0] = principal_normal(d[1], d[2], f.tangent[0], any_perpendicular(f.tangent[0]));
    propagate_rotation_minimising(f);  // which makes the binormals
    return f;
  }
  for (std::size_t i = 0; i < count; ++i) f.binormal[i] = glm::cross(f.tangent[i], f.normal[i]);
  return f;
}

}  // namespace knitc::sweep
