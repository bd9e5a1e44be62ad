#include "fibres/fibres.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "hashed_random.hpp"
#include "parallel.hpp"
#include "sweep/sweep.hpp"
#include "tubes/tubes.hpp"

namespace knitc::fibres {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

using hashed::mix;
// The numbers of one fibre, hair or loop, one after another.
struct Random {
  std::uint64_t key, n = 0;
  double uniform() { return hashed::uniform(key, n++); }
};
Random random_for(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d) {
  return {mix(mix(mix(mix(a) ^ b) ^ c) ^ d)};
}

// The plies as the sweep twists them: a plied section of the model's plies (or the yarn's
// own plied section), or the one round yarn.
sweep::CrossSection ply_section(const Yarn& yarn) {
  sweep::CrossSection c;
  c.radius = 0.5 * yarn.diameter;
  if (yarn.fibres.plies < 2) return c;
  c.shape = sweep::CrossSection::Shape::plied;
  c.plies = yarn.fibres.plies;
  const bool z = yarn.section == Section::plied && yarn.z_twist;  // plied S unless said
  c.twist = (z ? 1.0 : -1.0) * yarn.fibres.ply_twist / 100.0;
  return c;
}

// Where a fibre rests across its ply (a fraction of the ply's radius), by rejection from
// Zhao et al.'s density; only fibres in the outer shell are drawn, the rest lie hidden in
// the core.
double rest_radius(const yarn::FibreModel& m, Random& r) {
  const double lo = 0.85 * core, e = std::numbers::e;
  const double top = (1.0 - 2.0 * m.spread) * std::pow((e - std::exp(lo)) / (e - 1.0), m.packing) + m.spread;
  for (int tries = 0; tries < 64; ++tries) {
    const double R = lo + (1.0 - lo) * r.uniform();
    const double p = (1.0 - 2.0 * m.spread) * std::pow(std::max(0.0, (e - std::exp(R)) / (e - 1.0)), m.packing) + m.spread;
    if (r.uniform() * top <= p) return R;
  }
  return lo;
}

// A frame along a strand at the yarn's length s, interpolated between its samples.
// A strand's frame at any length along it, and where the strand is pressed flat (its
// `axes`), how much each of n and b is stretched over the round section's radius.
struct Along {
  const sweep::Frames& f;
  std::span<const double> arc;
  std::span<const glm::dvec2> axes = {};  // empty: round
  double round = 1.0;                      // the round section's radius
  std::size_t j = 0;
  glm::dvec2 squash{1.0};
  void at(double s, glm::dvec3& origin, glm::dvec3& n, glm::dvec3& b) {
    while (j + 2 < arc.size() && arc[j + 1] < s) ++j;
    while (j > 0 && arc[j] > s) --j;
    const double span = arc[j + 1] - arc[j];
    const double t = span > 0.0 ? std::clamp((s - arc[j]) / span, 0.0, 1.0) : 0.0;
    origin = glm::mix(f.origin[j], f.origin[j + 1], t);
    n = glm::normalize(glm::mix(f.normal[j], f.normal[j + 1], t));
    b = glm::normalize(glm::mix(f.binormal[j], f.binormal[j + 1], t));
    if (!axes.empty()) squash = glm::mix(axes[j], axes[j + 1], t) / round;
  }
};

// How one piece's fibres and flyaways are laid: counts first, so the arrays are sized once.
struct Plan {
  std::size_t fibre_points = 0;  // per fibre
  std::size_t hairs = 0, hair_points = 0, loops = 0;
};

Plan plan(const Yarn& yarn, const curves::CurvePiece& p) {
  Plan out;
  const yarn::FibreModel& m = yarn.fibres;
  const double length = p.arc_length.empty() ? 0.0 : p.arc_length.back();
  if (p.arc_length.size() < 2 || length <= 0.0) return out;
  const double turn = m.fibre_twist > 0.0 ? 100.0 / m.fibre_twist : 1e9;  // mm a turn
  const double step = std::min(max_step, turn / 16.0);
  out.fibre_points = static_cast<std::size_t>(std::ceil(length / step)) + 1;
  out.hairs = static_cast<std::size_t>(std::lround(m.hairs * length / 10.0));
  out.hair_points = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil(1.5 * m.hair_length / max_step)) + 1);
  out.loops = static_cast<std::size_t>(std::lround(m.loops * length / 10.0));
  return out;
}

std::size_t line_points(const Yarn& yarn, const Plan& plan) {
  const std::size_t fibres = static_cast<std::size_t>(std::max(1, yarn.fibres.plies)) * static_cast<std::size_t>(yarn.fibres.fibres_per_ply);
  return plan.fibre_points == 0 ? 0 : fibres * plan.fibre_points + plan.hairs * plan.hair_points;
}

struct PieceMesh {
  mesh::Primitive cores, lines;
};

void lay(const Yarn& yarn, std::size_t yarn_index, std::size_t piece_index, const curves::CurvePiece& p, double before,
         int sides, PieceMesh& out) {
  const Plan pl = plan(yarn, p);
  if (pl.fibre_points == 0) return;
  const yarn::FibreModel& m = yarn.fibres;
  const double length = p.arc_length.back(), yarn_radius = 0.5 * yarn.diameter;
  // Pressed where the relaxed yarns press each other, as the tube is (relax/press.hpp).
  const std::vector<sweep::Strand> plies = sweep::strands(p.frames, p.arc_length, ply_section(yarn), p.pressed);

  // The cores: each ply's tube, thinner.
  std::vector<sweep::Strand> cores = plies;
  for (sweep::Strand& s : cores) {
    s.along_normal *= core;
    s.along_binormal *= core;
    for (glm::dvec2& a : s.axes) a *= core;
  }
  sweep::append_tubes(cores, p.arc_length, tubes::ring_sides(yarn, sides), out.cores);
  const bool dyed = !yarn.colours.empty(), heathered = !yarn.heather.empty();
  const tubes::YarnColours rgb = tubes::yarn_colours(yarn);
  if (dyed) {
    out.cores.colors.resize(out.cores.positions.size());
    for (std::size_t v = 0; v < out.cores.positions.size(); ++v)
      out.cores.colors[v] = tubes::colour_along(yarn, rgb, before + static_cast<double>(out.cores.uvs[v].x));
  }
  if (heathered) out.cores.colors.assign(out.cores.positions.size(), tubes::mean_colour(yarn));  // the blend, deep inside
  const std::vector<glm::vec3>& fibre_rgb = rgb.fibres;
  glm::vec3 fibre_colour{1.0f};  // a heathered yarn's: the fibre being laid's

  const std::size_t points = line_points(yarn, pl);
  out.lines.mode = mesh::Mode::lines;
  out.lines.positions.reserve(points);
  if (dyed || heathered) out.lines.colors.reserve(points);
  const auto put = [&](const glm::dvec3& at, double s, bool join) {
    const auto k = static_cast<std::uint32_t>(out.lines.positions.size());
    out.lines.positions.emplace_back(at);
    if (dyed) out.lines.colors.push_back(tubes::colour_along(yarn, rgb, before + s));
    if (heathered) out.lines.colors.push_back(fibre_colour);
    if (join) out.lines.indices.insert(out.lines.indices.end(), {k - 1, k});
  };

  // Loop flyaways, each owned by one fibre: where it bulges, and how far.
  const std::size_t fibres_in_ply = static_cast<std::size_t>(m.fibres_per_ply);
  const std::size_t all_fibres = plies.size() * fibres_in_ply;
  struct Bulge {
    double s, reach;
  };
  std::vector<std::vector<Bulge>> bulges(all_fibres);
  for (std::size_t l = 0; l < pl.loops; ++l) {
    Random r = random_for(yarn_index, piece_index, 0x10095, l);
    const auto owner = static_cast<std::size_t>(r.uniform() * static_cast<double>(all_fibres)) % all_fibres;
    bulges[owner].push_back({r.uniform() * length, (0.3 + 0.7 * r.uniform()) * m.halo * yarn_radius});
  }
  constexpr double bulge_length = 1.5;  // mm of yarn a loop flyaway spans

  const double step = length / static_cast<double>(pl.fibre_points - 1);
  const double turns_per_mm = m.fibre_twist / 100.0;  // Z: against the S ply twist
  for (std::size_t ply = 0; ply < plies.size(); ++ply) {
    const sweep::Strand& strand = plies[ply];
    const double ply_radius = strand.along_normal;
    for (std::size_t f = 0; f < fibres_in_ply; ++f) {
      Random r = random_for(yarn_index, piece_index, ply, f);
      const double rest = rest_radius(m, r);
      const double theta0 = two_pi * r.uniform(), phase0 = two_pi * r.uniform();
      if (heathered) fibre_colour = fibre_rgb[yarn::fibre_colour_at(yarn.heather, r.uniform())];
      const std::vector<Bulge>& own = bulges[ply * fibres_in_ply + f];
      Along along{strand.frames, p.arc_length, strand.axes, ply_radius};
      for (std::size_t k = 0; k < pl.fibre_points; ++k) {
        const double s = std::min(length, static_cast<double>(k) * step);
        glm::dvec3 o, n, b;
        along.at(s, o, n, b);
        const double theta = theta0 + two_pi * turns_per_mm * s;
        const double swing = 0.5 * (std::cos((theta - theta0) / m.migration_period + phase0) + 1.0);
        double radius = ply_radius * rest * (m.migration + (1.0 - m.migration) * swing);
        for (const Bulge& g : own) {
          const double t = (s - g.s) / bulge_length;
          if (t > 0.0 && t < 1.0) radius += g.reach * 0.5 * (1.0 - std::cos(two_pi * t));
        }
        put(o + radius * (along.squash.x * std::cos(theta) * n + along.squash.y * std::sin(theta) * b), s, k > 0);
      }
    }
  }

  // Hairs: free fibre ends leaving the yarn's surface, in the yarn's own frame.
  Along yarn_frame{p.frames, p.arc_length};
  for (std::size_t h = 0; h < pl.hairs; ++h) {
    Random r = random_for(yarn_index, piece_index, 0x4a125, h);
    const double span = m.hair_length * (0.5 + r.uniform());
    const double s0 = r.uniform() * std::max(0.0, length - span);
    const double theta0 = two_pi * r.uniform(), sweep_angle = (r.uniform() - 0.5) * 3.0;
    const double reach = yarn_radius * (1.0 + m.halo * (0.3 + 0.7 * r.uniform()));
    if (heathered) fibre_colour = fibre_rgb[yarn::fibre_colour_at(yarn.heather, r.uniform())];
    for (std::size_t k = 0; k < pl.hair_points; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(pl.hair_points - 1);
      const double s = std::min(length, s0 + t * span);
      glm::dvec3 o, n, b;
      yarn_frame.at(s, o, n, b);
      const double theta = theta0 + t * sweep_angle;
      const double radius = 0.9 * yarn_radius + (reach - 0.9 * yarn_radius) * std::pow(t, 0.7);
      put(o + radius * (std::cos(theta) * n + std::sin(theta) * b), s, k > 0);
    }
  }
  assert(out.lines.positions.size() == points);
}

}  // namespace

std::uint64_t fibre_vertices(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces) {
  std::uint64_t total = 0;
  for (const curves::CurvePiece& p : pieces) {
    const Yarn& y = yarns[static_cast<std::size_t>(p.path.yarn)];
    total += line_points(y, plan(y, p));
  }
  return total;
}

mesh::Mesh build_mesh(std::span<const Yarn> yarns, std::span<const curves::CurvePiece> pieces, int sides, int threads) {
  mesh::Mesh out;
  const std::vector<int> material_of = tubes::add_materials(yarns, pieces, out);
  const std::vector<double> before = tubes::yarn_before(pieces);
  std::vector<PieceMesh> laid(pieces.size());
  parallel_for(pieces.size(), thread_count(threads), [&](std::size_t i) {
    const auto y = static_cast<std::size_t>(pieces[i].path.yarn);
    lay(yarns[y], y, i, pieces[i], before[i], sides, laid[i]);
  });
  // Per yarn, in the yarns' order: its cores, then its fibres, the pieces in order.
  for (std::size_t y = 0; y < yarns.size(); ++y) {
    if (material_of[y] < 0) continue;
    mesh::Primitive cores, lines;
    cores.material = lines.material = material_of[y];
    lines.mode = mesh::Mode::lines;
    lines.line_radius = static_cast<float>(0.5 * yarns[y].fibres.fibre_diameter);
    const auto append = [](mesh::Primitive& to, const mesh::Primitive& from) {
      const auto offset = static_cast<std::uint32_t>(to.positions.size());
      to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
      to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
      to.uvs.insert(to.uvs.end(), from.uvs.begin(), from.uvs.end());
      to.colors.insert(to.colors.end(), from.colors.begin(), from.colors.end());
      for (std::uint32_t k : from.indices) to.indices.push_back(k + offset);
    };
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (static_cast<std::size_t>(pieces[i].path.yarn) != y) continue;
      append(cores, laid[i].cores);
      append(lines, laid[i].lines);
      laid[i] = {};
    }
    if (!yarns[y].colours.empty() || !yarns[y].heather.empty()) out.materials[static_cast<std::size_t>(material_of[y])].base_color = glm::vec3(1.0f);
    if (!cores.indices.empty()) out.primitives.push_back(std::move(cores));
    if (!lines.indices.empty()) out.primitives.push_back(std::move(lines));
  }
  return out;
}

}  // namespace knitc::fibres
