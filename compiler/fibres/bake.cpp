#include "fibres/bake.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "hashed_random.hpp"
#include "parallel.hpp"
#include "tubes/tubes.hpp"

namespace knitc::fibres {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double pressed = 0.9;  // plies' centres, as a share of touching circles' offset

// The surface the tile shows: plies of radius `ply` whose centres turn at `offset` about
// the tube's axis, and the surface fibres round each ply.
struct Surface {
  double radius = 1.0;   // the tube's radius (mm): heights are measured from it
  int plies = 1;         // 1: a single strand filling the tube
  double ply = 1.0;      // mm
  double offset = 0.0;   // mm
  double slant = 1.0;    // cos of the ply's helix angle: its section is an ellipse this much longer round the tube
  double length = 10.0;  // mm of yarn the tile spans: one turn of the plies (or of the fibres, for one strand)
  double ply_turns = 0.0;  // turns of the plies in the tile, signed (+: as the ring's v turns)
  int fibres = 3;          // fibres round a ply
  int fibre_turns = 0;     // turns of each fibre about its ply in the tile (against the plies)
  // Stretches in the tile over which one fibre stays on the surface before it migrates
  // inward and another comes out in its place.
  int stretches = 1;
  double fibre_height = 0.01;  // mm a fibre's ridge stands
};

Surface surface_of(const Yarn& yarn) {
  const yarn::FibreModel& m = yarn.fibres;
  Surface s;
  const double yarn_radius = 0.5 * yarn.diameter;
  const double fibre_turns_per_mm = std::max(0.0, m.fibre_twist) / 100.0;
  if (yarn.section == Section::plied || m.plies < 2) {
    // One strand: the tube is the yarn (a singles) or one ply of a yarn the sweep plies.
    if (yarn.section == Section::plied) {
      const double gap = std::sin(std::numbers::pi / yarn.plies);
      s.radius = yarn_radius / (1.0 + 1.0 / gap);  // the sweep's ply radius
    } else {
      s.radius = yarn_radius;
    }
    s.ply = s.radius;
    s.length = fibre_turns_per_mm > 0.0 ? std::min(20.0, 1.0 / fibre_turns_per_mm) : 10.0;
  } else {
    // Plies twisted together press into each other: their centres a tenth nearer the axis
    // than touching circles', each wider so the yarn keeps its radius.
    const double gap = std::sin(std::numbers::pi / m.plies);
    s.radius = yarn_radius;
    s.plies = m.plies;
    s.offset = pressed * yarn_radius / (1.0 + gap);
    s.ply = yarn_radius - s.offset;
    const double ply_turns_per_mm = std::max(0.0, m.ply_twist) / 100.0;
    s.length = ply_turns_per_mm > 0.0 ? std::min(20.0, 1.0 / ply_turns_per_mm) : 10.0;
    // S unless the yarn says Z, as the fibres stage twists them; v turns as the sweep's ply angle.
    s.ply_turns = ply_turns_per_mm > 0.0 ? -1.0 : 0.0;
    const double tan_helix = two_pi * s.offset * ply_turns_per_mm;
    s.slant = 1.0 / std::sqrt(1.0 + tan_helix * tan_helix);
  }
  s.fibre_turns = static_cast<int>(std::lround(fibre_turns_per_mm * s.length));
  // A fibre surfaces for about a quarter of its migration period (a turn or so about the ply
  // for the presets, some 2 mm of wool), or 2 mm where it does not migrate or twist.
  const double surfaced = m.migration < 1.0 && fibre_turns_per_mm > 0.0 ? 0.25 * m.migration_period / fibre_turns_per_mm : 2.0;
  s.stretches = static_cast<int>(std::clamp(std::lround(s.length / std::max(0.25, surfaced)), 1L, 64L));
  // Round a ply: as many fibres as its circumference holds, but none narrower than four
  // texels, the ply's share of the tile's height.
  const double texels_round_ply = tile_round * s.ply / s.radius;
  const double across = two_pi * s.ply / std::max(1e-3, m.fibre_diameter);
  s.fibres = static_cast<int>(std::clamp(std::floor(std::min(across, texels_round_ply / 4.0)), 3.0, 512.0));
  s.fibre_height = 0.35 * std::numbers::pi * s.ply / s.fibres;  // a ridge about a third as high as it is wide
  return s;
}

// What the ray from the tube's axis at angle `phi`, `u` mm along the tile, meets.
struct Texel {
  double height = 0.0;  // mm from the tube's radius, <= 0
  std::uint64_t fibre = 0;  // which fibre shows: a hash of its ply, place round it and stretch along it
};

Texel texel_at(const Surface& s, double u, double phi) {
  double best = -1.0, best_x = 0.0, best_y = 0.0;
  int best_ply = 0;  // the ply the ray leaves last: the one on the surface there
  for (int k = 0; k < s.plies; ++k) {
    const double alpha = two_pi * (static_cast<double>(k) / s.plies + s.ply_turns * u / s.length);
    const double delta = std::remainder(phi - alpha, two_pi);
    const double c = std::cos(delta), sn = std::sin(delta);
    // Where the ray leaves the ply's section, an ellipse about (offset, 0), round the axis
    // longer by 1 / slant: (t c - d)^2 + (slant t sn)^2 = ply^2, the far root.
    const double a = c * c + s.slant * s.slant * sn * sn;
    const double disc = s.offset * s.offset * c * c - a * (s.offset * s.offset - s.ply * s.ply);
    if (disc < 0.0) continue;
    const double t = (s.offset * c + std::sqrt(disc)) / a;
    if (t > best) best = t, best_ply = k, best_x = t * c - s.offset, best_y = s.slant * t * sn;
  }
  Texel out;
  // Pressed plies meet in a V, about 0.68 of the radius deep for two.
  out.height = std::max(best, 0.0) - s.radius;
  // The surface fibres: fibre j sits at angle 2 pi (j / m + turns u / length) round its ply.
  const double psi = std::atan2(best_y, best_x) / two_pi;
  const double q = s.fibres * (psi - s.fibre_turns * u / s.length);
  const double fq = std::floor(q);
  const long long j = ((static_cast<long long>(fq) % s.fibres) + s.fibres) % s.fibres;
  const double across = 2.0 * (q - fq) - 1.0;  // -1 to 1 over the fibre
  // Along the yarn each place round the ply shows one fibre a stretch, the stretches of
  // neighbouring places staggered (a hash of j), so their ends do not line up.
  const double stagger = hashed::uniform(hashed::mix(static_cast<std::uint64_t>(j) + 0x57a66e7ULL), 0);
  const long long k = static_cast<long long>(std::floor(s.stretches * u / s.length + stagger)) % s.stretches;
  out.fibre = hashed::mix((static_cast<std::uint64_t>(best_ply) << 40) ^ (static_cast<std::uint64_t>(j) << 20) ^
                          static_cast<std::uint64_t>(k));
  const std::uint64_t key = out.fibre;
  const double stands = 0.5 + 0.5 * hashed::uniform(key, 0);  // some fibres lie deeper
  out.height += s.fibre_height * (stands * std::sqrt(std::max(0.0, 1.0 - across * across)) - 1.0);
  return out;
}

unsigned char byte(double v) { return static_cast<unsigned char>(std::clamp(std::lround(v * 255.0), 0L, 255L)); }

double srgb(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

BakedYarn bake(const Yarn& yarn, int threads) {
  const Surface s = surface_of(yarn);
  constexpr int w = tile_along, h = tile_round;
  const double dx = s.length / w, dy = two_pi * s.radius / h;  // mm a texel
  std::vector<Texel> texels(static_cast<std::size_t>(w) * h);
  // Row by row on the threads: each texel depends only on its place (and, below, on the
  // heights), so the maps are the same for any thread count.
  const int workers = thread_count(threads);
  parallel_for(static_cast<std::size_t>(h), workers, [&](std::size_t row) {
    const int j = static_cast<int>(row);
    for (int i = 0; i < w; ++i)
      texels[static_cast<std::size_t>(j) * w + i] = texel_at(s, (i + 0.5) * dx, two_pi * (j + 0.5) / h);
  });
  const auto at = [&](int i, int j) -> const Texel& {
    return texels[static_cast<std::size_t>((j % h + h) % h) * w + static_cast<std::size_t>((i % w + w) % w)];
  };

  BakedYarn out;
  out.length = s.length;
  out.fibres_round = s.fibres;
  out.fibre_turns = s.fibre_turns;
  out.normal = {w, h, 3, std::vector<unsigned char>(static_cast<std::size_t>(w) * h * 3)};
  out.occlusion = {w, h, 1, std::vector<unsigned char>(static_cast<std::size_t>(w) * h)};
  out.colour = {w, h, 3, std::vector<unsigned char>(static_cast<std::size_t>(w) * h * 3)};

  // The fibres' colours (linear): the heather's by share, else white; each fibre's shade.
  std::vector<glm::dvec3> heather;
  for (const glm::vec3& c : tubes::yarn_colours(yarn).fibres) heather.emplace_back(c);
  // Eight directions of the sky's horizon, six steps out to most of the radius.
  std::array<glm::dvec2, 8> directions;
  for (int d = 0; d < 8; ++d) directions[d] = {std::cos(two_pi * d / 8), std::sin(two_pi * d / 8)};
  const double reach = 0.8 * s.radius;

  parallel_for(static_cast<std::size_t>(h), workers, [&](std::size_t row) {
    const int j = static_cast<int>(row);
    for (int i = 0; i < w; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * w + i;
      const Texel& t = texels[p];
      // The normal from the heights' slopes: red along +u, green along +v (mesh/tangents.hpp).
      const double gx = (at(i + 1, j).height - at(i - 1, j).height) / (2.0 * dx);
      const double gy = (at(i, j + 1).height - at(i, j - 1).height) / (2.0 * dy);
      glm::dvec3 n = glm::normalize(glm::dvec3(-gx, -gy, 1.0));
      if (n.z < 0.2) {  // no steeper than 78 degrees: a crevice's wall still faces out
        const double k = std::sqrt(1.0 - 0.04) / std::hypot(n.x, n.y);
        n = {n.x * k, n.y * k, 0.2};
      }
      for (int c = 0; c < 3; ++c) out.normal.pixels[3 * p + c] = byte(0.5 * (n[c] + 1.0));

      // Occlusion: the mean sine of the horizon's elevation over eight directions; round the
      // tube the surface falls away by (distance^2) / 2r.
      double blocked = 0.0;
      for (const glm::dvec2& d : directions) {
        double steepest = 0.0;
        for (int step = 1; step <= 6; ++step) {
          const double r = reach * step / 6.0;
          const int di = static_cast<int>(std::lround(r * d.x / dx)), dj = static_cast<int>(std::lround(r * d.y / dy));
          const double round = r * d.y;
          const double rise = at(i + di, j + dj).height - t.height - round * round / (2.0 * s.radius);
          steepest = std::max(steepest, rise / r);
        }
        blocked += steepest / std::sqrt(1.0 + steepest * steepest);
      }
      out.occlusion.pixels[p] = byte(1.0 - blocked / directions.size());

      const std::uint64_t key = hashed::mix(t.fibre ^ 0xc01005ULL);
      const double shade = 0.9 + 0.1 * hashed::uniform(key, 0);
      glm::dvec3 colour(shade);
      if (!heather.empty()) colour *= heather[yarn::fibre_colour_at(yarn.heather, hashed::uniform(key, 1))];
      for (int c = 0; c < 3; ++c) out.colour.pixels[3 * p + c] = byte(srgb(colour[c]));
    }
  });
  return out;
}

void add_baked_textures(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, mesh::Mesh& mesh,
                        int threads) {
  const std::vector<int> material_of = tubes::material_indices(yarns, pieces);
  std::vector<std::size_t> used;
  for (std::size_t y = 0; y < yarns.size(); ++y)
    if (material_of[y] >= 0 && static_cast<std::size_t>(material_of[y]) < mesh.materials.size()) used.push_back(y);
  std::vector<BakedYarn> baked(used.size());
  for (std::size_t k = 0; k < used.size(); ++k) baked[k] = bake(yarns[used[k]], threads);
  for (std::size_t k = 0; k < used.size(); ++k) {
    const Yarn& yarn = yarns[used[k]];
    mesh::Material& m = mesh.materials[static_cast<std::size_t>(material_of[used[k]])];
    const int first = static_cast<int>(mesh.images.size());
    mesh.images.push_back(std::move(baked[k].normal));
    mesh.images.push_back(std::move(baked[k].occlusion));
    mesh.images.push_back(std::move(baked[k].colour));
    m.textures = {first, first + 1, first + 2, glm::vec2(static_cast<float>(baked[k].length), 1.0f)};
    if (yarn.heather.empty()) continue;
    // The heather is in the colour map now: the tube's speckle per vertex goes.
    m.base_color = glm::vec3(1.0f);
    const int material = material_of[used[k]];
    for (mesh::Primitive& p : mesh.primitives)
      if (p.material == material) p.colors.clear();
    for (mesh::Instances& group : mesh.instanced)
      for (mesh::Primitive& p : group.primitives)
        if (p.material == material) p.colors.clear();
  }
}

}  // namespace knitc::fibres
