// Pressing (issue 16): where relaxed yarns press on each other their sections flatten, an
// ellipse across the contact of the round section's area, varying smoothly along the
// yarn; so the visible surfaces pass into each other far less than round tubes would.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "relax/press.hpp"
#include "support.hpp"

namespace knitc {
namespace {

// Jersey in DK at a real gauge, relaxed: its yarns press where they cross. Relaxed once
// for both tests, for 120 sweeps (the pressing reads whatever the sweeps left; by then
// the cores are apart and the shells pressed).
struct Knitted {
  Pattern pattern;
  Fabric fabric;
};
const Knitted& relaxed_dk_jersey() {
  static const Knitted knitted = [] {
    const std::string source =
        "pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\" } }, knitting = \"flat\" }\n"
        "cast_on(8)\nfor _ = 1, 4 do row \"k\" row \"p\" end\nbind_off()\n";
    Knitted k;
    k.pattern = runtime::run_pattern(source, "jersey.lua").pattern;
    CompileOptions o;
    o.view = View::centreline;
    o.chord_tolerance = 0.05;
    o.relax = true;
    o.relaxation.max_iterations = 120;
    k.fabric = compile(k.pattern, o);
    return k;
  }();
  return knitted;
}

glm::dvec3 tangent_at(const std::vector<glm::dvec3>& p, std::size_t k) {
  const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < p.size() ? k + 1 : k;
  return glm::normalize(p[b] - p[a]);
}

// The radius of a point's section toward `u` (a unit vector across the yarn).
double radius_toward(const glm::dvec3& pressed, double free_radius, const glm::dvec3& u) {
  const double amount = glm::length(pressed);
  if (amount < 1e-12) return free_radius;
  const double root = std::sqrt(1.0 - amount);
  const double minor = free_radius * root, major = free_radius / root;
  const double c = glm::dot(u, pressed / amount), s2 = std::max(0.0, 1.0 - c * c);
  return 1.0 / std::sqrt(c * c / (minor * minor) + s2 / (major * major));
}

TEST(Press, SectionsFlattenAcrossTheContactsSmoothlyAndWithinBounds) {
  const Fabric& f = relaxed_dk_jersey().fabric;
  ASSERT_TRUE(f.relaxed);
  std::size_t pressed = 0, points = 0;
  double most = 0.0;
  for (const CurvePiece& piece : f.pieces) {
    const auto& p = piece.path;
    ASSERT_EQ(p.pressed.size(), p.data_points.size());
    for (std::size_t k = 0; k < p.pressed.size(); ++k) {
      ++points;
      const double amount = glm::length(p.pressed[k]);
      EXPECT_LE(amount, 1.0 - relax::flattest_aspect + 1e-12);
      most = std::max(most, amount);
      if (amount > 0.01) {
        ++pressed;
        EXPECT_LT(std::abs(glm::dot(p.pressed[k] / amount, tangent_at(p.data_points, k))), 1e-6);  // across the yarn
      }
      if (k > 0) {
        EXPECT_LT(std::abs(amount - glm::length(p.pressed[k - 1])), 0.1) << "point " << k;  // smoothly
      }
    }
  }
  // DK at 22 stitches to 10 cm is tight: most of the yarn is pressed somewhere, by up to
  // a fifth or more of its round height, never past the flattest.
  EXPECT_GT(static_cast<double>(pressed), 0.5 * static_cast<double>(points));
  EXPECT_GT(most, 0.15);
  // The curve pieces carry the pressing to every sample, for the sweep.
  for (const CurvePiece& piece : f.pieces) EXPECT_EQ(piece.pressed.size(), piece.samples.size());
}

TEST(Press, TheVisibleSurfacesPassIntoEachOtherLessThanRoundOnes) {
  const Fabric& f = relaxed_dk_jersey().fabric;
  const double free_radius = 0.5 * relaxed_dk_jersey().pattern.yarns[0].diameter;
  // Every point and the nearest point of another stretch of yarn within the free
  // diameter: how far the two sections reach into each other along the line between.
  struct At {
    std::size_t piece, k;
    double along;
  };
  std::vector<At> all;
  for (std::size_t i = 0; i < f.pieces.size(); ++i) {
    double s = 0.0;
    const auto& p = f.pieces[i].path.data_points;
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (k > 0) s += glm::distance(p[k - 1], p[k]);
      all.push_back({i, k, s});
    }
  }
  double round_overlap = 0.0, pressed_overlap = 0.0;
  std::size_t contacts = 0;
  for (std::size_t a = 0; a < all.size(); ++a) {
    const auto& pa = f.pieces[all[a].piece].path;
    const glm::dvec3 x = pa.data_points[all[a].k];
    double nearest = 2.0 * free_radius;
    std::size_t best = all.size();
    for (std::size_t b = 0; b < all.size(); ++b) {
      if (all[b].piece == all[a].piece && std::abs(all[b].along - all[a].along) <= 3.6 * free_radius) continue;
      const double d = glm::distance(x, f.pieces[all[b].piece].path.data_points[all[b].k]);
      if (d < nearest) nearest = d, best = b;
    }
    if (best == all.size()) continue;
    const auto& pb = f.pieces[all[best].piece].path;
    const glm::dvec3 y = pb.data_points[all[best].k];
    glm::dvec3 u = (y - x) / nearest;
    const glm::dvec3 ta = tangent_at(pa.data_points, all[a].k), tb = tangent_at(pb.data_points, all[best].k);
    const glm::dvec3 ua = glm::normalize(u - glm::dot(u, ta) * ta), ub = glm::normalize(-u - glm::dot(-u, tb) * tb);
    round_overlap += 2.0 * free_radius - nearest;
    pressed_overlap += std::max(0.0, radius_toward(pa.pressed[all[a].k], free_radius, ua) +
                                         radius_toward(pb.pressed[all[best].k], free_radius, ub) - nearest);
    ++contacts;
  }
  ASSERT_GT(contacts, 100u);
  RecordProperty("round_overlap_mm", std::to_string(round_overlap / static_cast<double>(contacts)));
  RecordProperty("pressed_overlap_mm", std::to_string(pressed_overlap / static_cast<double>(contacts)));
  EXPECT_LT(pressed_overlap, 0.6 * round_overlap);
}

}  // namespace
}  // namespace knitc
