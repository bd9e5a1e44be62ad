// Cross-sections swept along frames: round, flattened and plied yarns as closed tubes.
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "sweep/sweep.hpp"

namespace knitc::sweep {

namespace {

using glm::dvec3;

// Frames whose binormal follows `flat` as closely as each tangent allows: the minor axis
// of a yarn pressed flat. Where the tangent runs along `flat`, the previous axis is kept.
Frames flattened(const Frames& f, const dvec3& flat) {
  Frames out = f;
  dvec3 previous = f.binormal[0];
  for (std::size_t i = 0; i < f.size(); ++i) {
    const dvec3& t = f.tangent[i];
    dvec3 b = flat - glm::dot(flat, t) * t;
    if (glm::length(b) < 1e-3) b = previous - glm::dot(previous, t) * t;
    b = glm::normalize(b);
    out.binormal[i] = b;
    out.normal[i] = glm::cross(b, t);  // (t, n, b) stays right-handed: b = t x n
    previous = b;
  }
  return out;
}

// A round section pressed flat where `pressed` says (see strands): the frames turned by
// the angle of the minor axis in the (normal, binormal) plane, kept where not pressed and
// taken the nearest way round (an ellipse turned half a turn is itself).
Strand pressed_circle(const Frames& f, double r, std::span<const dvec3> pressed) {
  Strand out{f, r, r, std::vector<glm::dvec2>(f.size(), glm::dvec2(r))};
  double theta = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const dvec3& v = pressed[i];
    const double amount = glm::length(v);
    if (amount > 1e-9) {
      double target = std::atan2(glm::dot(v, f.binormal[i]), glm::dot(v, f.normal[i]));
      while (target - theta > 0.5 * std::numbers::pi) target -= std::numbers::pi;
      while (target - theta < -0.5 * std::numbers::pi) target += std::numbers::pi;
      theta = target;
    }
    const dvec3 n = std::cos(theta) * f.normal[i] + std::sin(theta) * f.binormal[i];
    out.frames.normal[i] = n;
    out.frames.binormal[i] = glm::cross(f.tangent[i], n);
    const double root = std::sqrt(1.0 - std::min(amount, 0.95));
    out.axes[i] = glm::dvec2(r * root, r / root);  // the minor axis along the pressing
  }
  return out;
}

// The centre line of ply k of n: a helix about the yarn's centreline at distance
// `offset`, turning `twist` times per mm in the rotation-minimising frame. Where the yarn
// is pressed (`squash`, per frame or empty: the round section's pressed frame and its
// half-axes over the radius, from pressed_circle) the helix is squashed onto that ellipse:
// the plies spread along the major axis, the twist's phase still the frame's.
Frames ply(const Frames& f, std::span<const double> s, int k, int n, double offset, double twist, const Strand* squash,
           double radius) {
  Frames p;
  const std::size_t count = f.size();
  p.origin.resize(count);
  p.tangent.resize(count);
  p.normal.resize(count);
  p.binormal.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double phi = 2.0 * std::numbers::pi * (static_cast<double>(k) / n + twist * s[i]);
    dvec3 out = offset * (std::cos(phi) * f.normal[i] + std::sin(phi) * f.binormal[i]);
    if (squash != nullptr) {
      const Frames& q = squash->frames;
      const glm::dvec2 scale = squash->axes[i] / radius;
      out = scale.x * glm::dot(out, q.normal[i]) * q.normal[i] + scale.y * glm::dot(out, q.binormal[i]) * q.binormal[i];
    }
    p.origin[i] = f.origin[i] + out;
  }
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == count ? i : i + 1;
    p.tangent[i] = glm::normalize(p.origin[b] - p.origin[a]);
  }
  const dvec3 n0 = f.normal[0] - glm::dot(f.normal[0], p.tangent[0]) * p.tangent[0];
  p.normal[0] = glm::normalize(n0);
  propagate_rotation_minimising(p);
  return p;
}

struct Trig {
  std::vector<double> cosines, sines;
  explicit Trig(int sides) : cosines(sides), sines(sides) {
    for (int k = 0; k < sides; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / sides;
      cosines[k] = std::cos(theta);
      sines[k] = std::sin(theta);
    }
  }
};

// Writes into arrays sized in advance: each tube lands at its own offsets, so pieces can
// be written in parallel into one primitive without a copy.
struct Cursor {
  mesh::Primitive& out;
  std::size_t vertex, index;
  std::uint32_t put(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
    out.positions[vertex] = p;
    out.normals[vertex] = n;
    out.uvs[vertex] = uv;
    return static_cast<std::uint32_t>(vertex++);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.indices[index++] = a;
    out.indices[index++] = b;
    out.indices[index++] = c;
  }
};

// One strand's rings: `sides` + 1 vertices each (the last repeats the first, v = 1).
std::uint32_t write_rings(const Strand& strand, std::span<const double> s, const Trig& trig, Cursor& c) {
  const Frames& f = strand.frames;
  const int sides = static_cast<int>(trig.cosines.size());
  const auto first = static_cast<std::uint32_t>(c.vertex);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double a = strand.axes.empty() ? strand.along_normal : strand.axes[i].x;
    const double b = strand.axes.empty() ? strand.along_binormal : strand.axes[i].y;
    const std::uint32_t ring = static_cast<std::uint32_t>(c.vertex);
    for (int k = 0; k < sides; ++k) {
      const double ck = trig.cosines[k], sk = trig.sines[k];
      // The ellipse's outward normal is along (cos / a, sin / b), that is (b cos, a sin).
      c.put(glm::vec3(f.origin[i] + a * ck * f.normal[i] + b * sk * f.binormal[i]),
            glm::normalize(glm::vec3(b * ck * f.normal[i] + a * sk * f.binormal[i])),
            glm::vec2(static_cast<float>(s[i]), static_cast<float>(k) / static_cast<float>(sides)));
    }
    c.put(c.out.positions[ring], c.out.normals[ring], glm::vec2(static_cast<float>(s[i]), 1.0f));
  }
  return first;
}

// Two triangles between each pair of consecutive rings (sides + 1 vertices each, from
// `base`): (i, k), (i, k+1), (i+1, k), (i+1, k+1); the side direction crossed with the
// tangent points outward.
void write_quads(std::uint32_t base, std::size_t rings, int sides, Cursor& c) {
  const auto stride = static_cast<std::uint32_t>(sides + 1);
  for (std::size_t i = 0; i + 1 < rings; ++i) {
    const auto row = base + static_cast<std::uint32_t>(i) * stride;
    for (int k = 0; k < sides; ++k) {
      const std::uint32_t a = row + k, b = row + k + 1, cc = a + stride, d = b + stride;
      c.triangle(a, b, cc);
      c.triangle(b, d, cc);
    }
  }
}

// A flat cap: a centre vertex and a copy of the ring's rim with the cap's normal.
void write_cap(const Frames& f, std::size_t ring, std::uint32_t rim, int sides, bool at_start, Cursor& c) {
  const glm::vec3 normal(at_start ? -f.tangent[ring] : f.tangent[ring]);
  const std::uint32_t centre = c.put(glm::vec3(f.origin[ring]), normal, glm::vec2(c.out.uvs[rim].x, 0.5f));
  for (int k = 0; k < sides; ++k) c.put(c.out.positions[rim + k], normal, c.out.uvs[rim + k]);
  for (int k = 0; k < sides; ++k) {
    const std::uint32_t a = centre + 1 + k, b = centre + 1 + (k + 1) % sides;
    // Counter-clockwise seen from outside: from -t at the start, from +t at the end.
    if (at_start) c.triangle(centre, b, a);
    else c.triangle(centre, a, b);
  }
}

}  // namespace

std::vector<Strand> strands(const Frames& f, std::span<const double> s, const CrossSection& section,
                            std::span<const dvec3> pressed) {
  assert(f.size() == s.size());
  assert(pressed.empty() || pressed.size() == f.size());
  const double r = section.radius;
  switch (section.shape) {
    case CrossSection::Shape::circle:
      if (!pressed.empty()) return {pressed_circle(f, r, pressed)};
      return {Strand{f, r, r, {}}};
    case CrossSection::Shape::ellipse: {
      // Same area as the circle: major r / sqrt(aspect) in the fabric, minor r sqrt(aspect) across it.
      const double root = std::sqrt(section.aspect);
      return {Strand{flattened(f, section.flat_normal), r / root, r * root, {}}};
    }
    case CrossSection::Shape::plied: {
      const int n = section.plies;
      // n touching circles around the axis: centres at R = r_p / sin(pi / n), R + r_p = r.
      const double gap = std::sin(std::numbers::pi / n);
      const double ply_radius = r / (1.0 + 1.0 / gap), offset = ply_radius / gap;
      // Pressed, the plies' centres lie on the flattened section's ellipse (each ply stays round).
      const Strand squash = pressed.empty() ? Strand{} : pressed_circle(f, r, pressed);
      std::vector<Strand> out;
      for (int k = 0; k < n; ++k)
        out.push_back({ply(f, s, k, n, offset, section.twist, pressed.empty() ? nullptr : &squash, r), ply_radius, ply_radius, {}});
      return out;
    }
  }
  return {};
}

TubeSize tube_size(std::size_t rings, int sides, std::size_t strands) {
  const auto n = static_cast<std::size_t>(sides);
  return {strands * (rings * (n + 1) + 2 * (n + 1)), strands * ((rings - 1) * n * 6 + 2 * n * 3)};
}

void write_tubes(std::span<const Strand> strands, std::span<const double> s, int sides, mesh::Primitive& out,
                 std::size_t vertex_offset, std::size_t index_offset) {
  assert(sides >= 3 && out.mode == mesh::Mode::triangles);
  const Trig trig(sides);
  const auto stride = static_cast<std::uint32_t>(sides + 1);
  Cursor c{out, vertex_offset, index_offset};
  for (const Strand& strand : strands) {
    const Frames& f = strand.frames;
    assert(f.size() >= 2 && f.size() == s.size());
    const std::uint32_t base = write_rings(strand, s, trig, c);
    const auto rings = f.size();
    write_quads(base, rings, sides, c);
    write_cap(f, 0, base, sides, true, c);
    write_cap(f, rings - 1, base + static_cast<std::uint32_t>(rings - 1) * stride, sides, false, c);
  }
  assert(c.vertex - vertex_offset == tube_size(s.size(), sides, strands.size()).vertices);
  assert(c.index - index_offset == tube_size(s.size(), sides, strands.size()).indices);
}

TubeSize stretch_size(const Stretch& stretch, int sides) {
  const auto n = static_cast<std::size_t>(sides);
  const std::size_t rings = stretch.last - stretch.first + 1, caps = (stretch.cap_start ? 1 : 0) + (stretch.cap_end ? 1 : 0);
  return {rings * (n + 1) + caps * (n + 1), (rings - 1) * n * 6 + caps * n * 3};
}

double seam_angle(const Strand& strand, std::size_t i) {
  const Frames& f = strand.frames;
  const dvec3& t = f.tangent[i];
  dvec3 c = dvec3(0.0, 0.0, 1.0) - t.z * t;
  if (glm::length(c) < 0.3) c = dvec3(1.0, 0.0, 0.0) - t.x * t;
  return std::atan2(glm::dot(c, f.binormal[i]), glm::dot(c, f.normal[i]));
}

void write_stretch(const Strand& strand, const Stretch& stretch, std::span<const double> u, std::span<const double> phase,
                   const glm::dvec3& offset, int sides, mesh::Primitive& out, std::size_t vertex_offset, std::size_t index_offset) {
  assert(sides >= 3 && out.mode == mesh::Mode::triangles && stretch.last > stretch.first);
  const std::size_t rings = stretch.last - stretch.first + 1;
  assert(u.size() == rings && phase.size() == rings);
  const Trig trig(sides);
  const auto stride = static_cast<std::uint32_t>(sides + 1);
  Cursor c{out, vertex_offset, index_offset};
  const Frames& f = strand.frames;
  const auto base = static_cast<std::uint32_t>(c.vertex);
  for (std::size_t r = 0; r < rings; ++r) {
    const std::size_t i = stretch.first + r;
    const double a = strand.axes.empty() ? strand.along_normal : strand.axes[i].x;
    const double b = strand.axes.empty() ? strand.along_binormal : strand.axes[i].y;
    const double cp = std::cos(phase[r]), sp = std::sin(phase[r]);
    const dvec3 origin = f.origin[i] - offset;
    const std::uint32_t ring = static_cast<std::uint32_t>(c.vertex);
    for (int k = 0; k < sides; ++k) {
      const double ck = trig.cosines[k] * cp - trig.sines[k] * sp, sk = trig.sines[k] * cp + trig.cosines[k] * sp;
      c.put(glm::vec3(origin + a * ck * f.normal[i] + b * sk * f.binormal[i]),
            glm::normalize(glm::vec3(b * ck * f.normal[i] + a * sk * f.binormal[i])),
            glm::vec2(static_cast<float>(u[r]), static_cast<float>(k) / static_cast<float>(sides)));
    }
    c.put(c.out.positions[ring], c.out.normals[ring], glm::vec2(static_cast<float>(u[r]), 1.0f));
  }
  write_quads(base, rings, sides, c);
  // The caps' centres in the tile's frame too: write_cap reads the frame's origin.
  if (stretch.cap_start || stretch.cap_end) {
    Frames ends;
    for (const std::size_t i : {stretch.first, stretch.last}) {
      ends.origin.push_back(f.origin[i] - offset);
      ends.tangent.push_back(f.tangent[i]);
    }
    if (stretch.cap_start) write_cap(ends, 0, base, sides, true, c);
    if (stretch.cap_end) write_cap(ends, 1, base + static_cast<std::uint32_t>(rings - 1) * stride, sides, false, c);
  }
  assert(c.vertex - vertex_offset == stretch_size(stretch, sides).vertices);
  assert(c.index - index_offset == stretch_size(stretch, sides).indices);
}

void append_tubes(std::span<const Strand> strands, std::span<const double> s, int sides, mesh::Primitive& out) {
  const TubeSize size = tube_size(s.size(), sides, strands.size());
  const std::size_t v = out.positions.size(), i = out.indices.size();
  out.positions.resize(v + size.vertices);
  out.normals.resize(v + size.vertices);
  out.uvs.resize(v + size.vertices);
  out.indices.resize(i + size.indices);
  write_tubes(strands, s, sides, out, v, i);
}

void append_wireframe(std::span<const Strand> strands, int sides, mesh::Primitive& out) {
  assert(sides >= 3 && out.mode == mesh::Mode::lines);
  const Trig trig(sides);
  for (const Strand& strand : strands) {
    const Frames& f = strand.frames;
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double a = strand.axes.empty() ? strand.along_normal : strand.axes[i].x;
      const double b = strand.axes.empty() ? strand.along_binormal : strand.axes[i].y;
      for (int k = 0; k < sides; ++k)
        out.positions.emplace_back(f.origin[i] + a * trig.cosines[k] * f.normal[i] + b * trig.sines[k] * f.binormal[i]);
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto row = base + static_cast<std::uint32_t>(i * sides);
      for (int k = 0; k < sides; ++k) {
        const std::uint32_t a = row + k;
        out.indices.insert(out.indices.end(), {a, row + (k + 1) % sides});  // around the ring
        if (i + 1 < f.size()) out.indices.insert(out.indices.end(), {a, a + sides});  // along
      }
    }
  }
}

}  // namespace knitc::sweep
