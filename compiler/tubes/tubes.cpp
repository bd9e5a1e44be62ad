#include "tubes/tubes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

#include "hashed_random.hpp"
#include "parallel.hpp"

namespace knitc::tubes {

sweep::CrossSection cross_section(const Yarn& yarn) {
  sweep::CrossSection c;
  c.radius = 0.5 * yarn.diameter;
  switch (yarn.section) {
    case Section::circle: c.shape = sweep::CrossSection::Shape::circle; break;
    case Section::ellipse:
      c.shape = sweep::CrossSection::Shape::ellipse;
      c.aspect = yarn.aspect;
      c.flat_normal = {0.0, 0.0, 1.0};  // pressed flat in the fabric's plane
      break;
    case Section::plied:
      c.shape = sweep::CrossSection::Shape::plied;
      c.plies = yarn.plies;
      c.twist = (yarn.z_twist ? 1.0 : -1.0) * yarn.twist / 100.0;  // turns per mm
      break;
  }
  return c;
}

glm::vec3 linear_rgb(const std::string& hex) {
  assert(hex.size() == 7 && hex[0] == '#');
  glm::vec3 rgb;
  for (int i = 0; i < 3; ++i) {
    const double s = static_cast<double>(std::strtol(hex.substr(1 + 2 * i, 2).c_str(), nullptr, 16)) / 255.0;
    rgb[i] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
  }
  return rgb;
}

int ring_sides(const Yarn& yarn, int sides) { return yarn.section == Section::plied ? std::max(5, (sides + 1) / 2) : sides; }

std::size_t strand_count(const Yarn& yarn) { return yarn.section == Section::plied ? static_cast<std::size_t>(yarn.plies) : 1; }

std::uint64_t vertex_count(const Yarn& yarn, std::size_t samples, int sides) {
  return sweep::tube_size(samples, ring_sides(yarn, sides), strand_count(yarn)).vertices;
}

namespace {

mesh::Mode primitive_mode(View view) {
  switch (view) {
    case View::surface: return mesh::Mode::triangles;
    case View::wireframe: return mesh::Mode::lines;
    case View::centreline: return mesh::Mode::line_strip;
  }
  return mesh::Mode::triangles;
}

}  // namespace

YarnColours yarn_colours(const Yarn& yarn) {
  YarnColours c;
  for (const yarn::ColourRun& r : yarn.colours) c.runs.push_back(linear_rgb(r.color));
  for (const yarn::FibreColour& f : yarn.heather) c.fibres.push_back(linear_rgb(f.color));
  c.plain = linear_rgb(yarn.color);
  return c;
}

glm::vec3 colour_along(const Yarn& yarn, const YarnColours& c, double s) {
  assert(c.runs.size() == yarn.colours.size());
  if (yarn.colours.empty()) return c.plain;
  return c.runs[yarn::run_at(yarn.colours, yarn.colour_start, std::max(0.0, s))];
}

std::vector<double> yarn_before(std::span<const curves::CurvePiece> pieces) {
  std::vector<double> before(pieces.size(), 0.0);
  int yarn = -1;
  double length = 0.0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (pieces[i].path.yarn != yarn) yarn = pieces[i].path.yarn, length = 0.0;
    before[i] = length;
    if (!pieces[i].arc_length.empty()) length += pieces[i].arc_length.back();
  }
  return before;
}

glm::vec3 mean_colour(const Yarn& yarn) {
  glm::dvec3 sum{0.0};
  double total = 0.0;
  for (const yarn::ColourRun& r : yarn.colours) sum += glm::dvec3(linear_rgb(r.color)) * r.length, total += r.length;
  for (const yarn::FibreColour& f : yarn.heather) sum += glm::dvec3(linear_rgb(f.color)) * f.share, total += f.share;
  return total > 0.0 ? glm::vec3(sum / total) : linear_rgb(yarn.color);
}

std::vector<int> material_indices(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces) {
  std::vector<int> material_of(yarns.size(), -1);
  for (const curves::CurvePiece& p : pieces) material_of[static_cast<std::size_t>(p.path.yarn)] = 0;
  int next = 0;
  for (int& m : material_of)
    if (m == 0) m = next++;
  return material_of;
}

std::vector<int> add_materials(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, mesh::Mesh& mesh) {
  const std::size_t first = mesh.materials.size();
  std::vector<int> material_of = material_indices(yarns, pieces);
  for (std::size_t y = 0; y < yarns.size(); ++y) {
    if (material_of[y] < 0) continue;
    material_of[y] += static_cast<int>(first);
    const glm::vec3 colour = mean_colour(yarns[y]);
    mesh.materials.push_back({yarns[y].id, colour, colour, 0.5f});
  }
  return material_of;
}

mesh::Mesh build_mesh(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, View view, int sides,
                      int threads) {
  mesh::Mesh out;
  const std::vector<int> material_of = add_materials(yarns, pieces, out);
  const mesh::Mode mode = primitive_mode(view);
  if (mode == mesh::Mode::line_strip) {
    // glTF has no primitive restart: a line strip per piece.
    for (const curves::CurvePiece& p : pieces) {
      mesh::Primitive prim;
      prim.material = material_of[p.path.yarn];
      prim.mode = mode;
      for (const auto& o : p.frames.origin) {
        prim.indices.push_back(static_cast<std::uint32_t>(prim.positions.size()));
        prim.positions.emplace_back(o);
      }
      out.primitives.push_back(std::move(prim));
    }
    return out;
  }
  if (mode == mesh::Mode::triangles) {
    // Every piece's place in its yarn's primitive is known from its sample count: the
    // arrays are sized once and each piece's tubes are written straight into them, in
    // parallel, with the same bytes for any thread count.
    std::vector<std::size_t> vertex_at(pieces.size()), vertex_end(pieces.size()), index_at(pieces.size());
    std::vector<std::size_t> vertices(yarns.size(), 0), indices(yarns.size(), 0);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const int y = pieces[i].path.yarn;
      const Yarn& yarn = yarns[y];
      const auto size = sweep::tube_size(pieces[i].samples.size(), ring_sides(yarn, sides), strand_count(yarn));
      vertex_at[i] = vertices[y];
      index_at[i] = indices[y];
      vertices[y] += size.vertices;
      vertex_end[i] = vertices[y];
      indices[y] += size.indices;
    }
    std::vector<mesh::Primitive> by_yarn(yarns.size());
    for (std::size_t y = 0; y < by_yarn.size(); ++y) {  // one allocation per array
      by_yarn[y].material = material_of[y];
      by_yarn[y].mode = mode;
      by_yarn[y].positions.resize(vertices[y]);
      by_yarn[y].normals.resize(vertices[y]);
      by_yarn[y].uvs.resize(vertices[y]);
      if (!yarns[y].colours.empty() || !yarns[y].heather.empty()) {
        by_yarn[y].colors.resize(vertices[y]);
        if (material_of[y] >= 0) out.materials[static_cast<std::size_t>(material_of[y])].base_color = glm::vec3(1.0f);
      }
      by_yarn[y].indices.resize(indices[y]);
    }
    const std::vector<double> before = yarn_before(pieces);
    std::vector<YarnColours> colours;
    for (const Yarn& y : yarns) colours.push_back(yarn_colours(y));
    parallel_for(pieces.size(), thread_count(threads), [&](std::size_t i) {
      const curves::CurvePiece& p = pieces[i];
      const Yarn& yarn = yarns[p.path.yarn];
      const auto strands = sweep::strands(p.frames, p.arc_length, cross_section(yarn), p.pressed);
      mesh::Primitive& prim = by_yarn[p.path.yarn];
      sweep::write_tubes(strands, p.arc_length, ring_sides(yarn, sides), prim, vertex_at[i], index_at[i]);
      if (prim.colors.empty()) return;
      // Each vertex by its length along the yarn (TEXCOORD u, the piece's own).
      const YarnColours& rgb = colours[static_cast<std::size_t>(p.path.yarn)];
      if (!yarn.heather.empty()) {
        // Heathered: each vertex a fibre colour by its share, drawn from a hash of the piece
        // and the vertex: a fine speckle where the fibres' colours show through each other.
        const std::uint64_t key = hashed::mix(static_cast<std::uint64_t>(i) + 0x4ea7e5ULL);
        for (std::size_t v = vertex_at[i]; v < vertex_end[i]; ++v)
          prim.colors[v] = rgb.fibres[yarn::fibre_colour_at(yarn.heather, hashed::uniform(key, v - vertex_at[i]))];
        return;
      }
      for (std::size_t v = vertex_at[i]; v < vertex_end[i]; ++v)
        prim.colors[v] = colour_along(yarn, rgb, before[i] + static_cast<double>(prim.uvs[v].x));
    });
    for (auto& prim : by_yarn) {
      if (!prim.indices.empty()) out.primitives.push_back(std::move(prim));
    }
    return out;
  }
  // Wireframes: each piece's lines, then one primitive per yarn, the pieces in order.
  std::vector<mesh::Primitive> lines(pieces.size());
  parallel_for(pieces.size(), thread_count(threads), [&](std::size_t i) {
    const curves::CurvePiece& p = pieces[i];
    const Yarn& yarn = yarns[p.path.yarn];
    lines[i].mode = mode;
    sweep::append_wireframe(sweep::strands(p.frames, p.arc_length, cross_section(yarn), p.pressed), ring_sides(yarn, sides), lines[i]);
  });
  for (std::size_t y = 0; y < yarns.size(); ++y) {
    mesh::Primitive prim;
    prim.material = material_of[y];
    prim.mode = mode;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (pieces[i].path.yarn != static_cast<int>(y)) continue;
      const auto offset = static_cast<std::uint32_t>(prim.positions.size());
      prim.positions.insert(prim.positions.end(), lines[i].positions.begin(), lines[i].positions.end());
      for (std::uint32_t index : lines[i].indices) prim.indices.push_back(index + offset);
    }
    if (!prim.indices.empty()) out.primitives.push_back(std::move(prim));
  }
  return out;
}


}  // namespace knitc::tubes
