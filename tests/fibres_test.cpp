// A yarn's fibres (--section fibres): the model's presets and fields, the fibres' twist and
// migration measured on a straight yarn, flyaways reaching out as far as the halo says, and
// the same bytes for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "fibres/fibres.hpp"
#include "support.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

Pattern run(const std::string& yarn) {
  return runtime::run_pattern("pattern { gauge = { stitches = 22, rows = 30 }, yarns = { A = { weight = \"dk\", " + yarn +
                                  " } }, knitting = \"flat\" }\ncast_on(4)\nrow \"k\"\nrow \"p\"\nrow \"k\"\nbind_off()\n",
                              "t.lua")
      .pattern;
}

std::string error_of(const std::string& yarn) {
  try {
    run(yarn);
  } catch (const runtime::PatternError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Fibres, EachFibreHasAPresetAndEveryPartIsOverridable) {
  EXPECT_EQ(run("").yarns[0].fibres, yarn::fibre_preset("wool"));
  const yarn::FibreModel mohair = run("fibre = \"mohair\"").yarns[0].fibres;
  EXPECT_EQ(mohair, yarn::fibre_preset("mohair"));
  EXPECT_GT(mohair.hairs, 4 * yarn::fibre_preset("wool").hairs);  // the halo
  EXPECT_GT(mohair.halo, yarn::fibre_preset("wool").halo);
  const yarn::FibreModel m = run("fibre = \"cotton\", fibre_count = 7, fibre_diameter = 0.03, fibre_twist = 0, fibre_packing = 2, "
                                 "fibre_spread = 0, migration = 1, migration_period = 3, hairs = 0, hair_length = 4, loops = 0, "
                                 "halo = 0")
                                 .yarns[0]
                                 .fibres;
  EXPECT_EQ(m.plies, 3);  // cotton's
  EXPECT_EQ(m.fibres_per_ply, 7);
  EXPECT_DOUBLE_EQ(m.fibre_diameter, 0.03);
  EXPECT_DOUBLE_EQ(m.fibre_twist, 0.0);
  EXPECT_DOUBLE_EQ(m.packing, 2.0);
  EXPECT_DOUBLE_EQ(m.spread, 0.0);
  EXPECT_DOUBLE_EQ(m.migration, 1.0);
  EXPECT_DOUBLE_EQ(m.migration_period, 3.0);
  EXPECT_DOUBLE_EQ(m.hairs, 0.0);
  EXPECT_DOUBLE_EQ(m.hair_length, 4.0);
  EXPECT_DOUBLE_EQ(m.loops, 0.0);
  EXPECT_DOUBLE_EQ(m.halo, 0.0);
  // A yarn declared plied gives the fibres its plies and twist.
  const yarn::FibreModel plied = run("section = \"plied\", plies = 4, twist = 30").yarns[0].fibres;
  EXPECT_EQ(plied.plies, 4);
  EXPECT_DOUBLE_EQ(plied.ply_twist, 30.0);
  EXPECT_EQ(error_of("hairs = -1"), "t.lua:1: yarns.A.hairs is -1 per cm; it must be 0 to 500 per cm");
  EXPECT_EQ(error_of("fibre_count = 0"), "t.lua:1: yarns.A.fibre_count is 0; it must be from 1 to 1000");
  EXPECT_EQ(error_of("fibre_diameter = 0"),
            "t.lua:1: yarns.A.fibre_diameter is 0 mm; it must be more than 0 mm and at most 0.5 mm");
}

// A straight yarn along +X, 40 mm, traced as the compiler traces a piece.
curves::CurvePiece straight(const Yarn& yarn) {
  yarn_paths::Piece path;
  for (int i = 0; i <= 40; ++i) path.data_points.emplace_back(static_cast<double>(i), 0.0, 0.0);
  return curves::trace(std::move(path), yarn, curves::Options{});
}

TEST(Fibres, OnAStraightYarnEachFibreTurnsAtItsTwistWithinItsPly) {
  Yarn yarn;
  yarn.color = "#d9c8a9";
  yarn.diameter = 2.0;
  yarn.fibres.plies = 1;  // one ply: the fibres turn about the yarn's own axis
  yarn.fibres.fibres_per_ply = 5;
  yarn.fibres.fibre_twist = 50.0;  // turns per 10 cm: 20 turns over 40 mm
  yarn.fibres.migration = 1.0;     // no migration: each fibre keeps its radius
  yarn.fibres.hairs = yarn.fibres.loops = 0.0;
  const std::vector<curves::CurvePiece> pieces{straight(yarn)};
  const std::vector<Yarn> yarns{yarn};
  const mesh::Mesh m = fibres::build_mesh(yarns, pieces, 12, 1);
  ASSERT_EQ(m.primitives.size(), 2u);
  const mesh::Primitive& lines = m.primitives[1];
  EXPECT_EQ(lines.mode, mesh::Mode::lines);
  EXPECT_FLOAT_EQ(lines.line_radius, 0.5f * 0.022f);
  EXPECT_EQ(lines.positions.size(), fibres::fibre_vertices(yarns, pieces));
  const std::size_t per_fibre = lines.positions.size() / 5;
  for (std::size_t f = 0; f < 5; ++f) {
    double turned = 0.0, r0 = -1.0;
    for (std::size_t k = 0; k < per_fibre; ++k) {
      const glm::vec3 p = lines.positions[f * per_fibre + k];
      const double r = std::hypot(p.y, p.z);
      if (r0 < 0.0) r0 = r;
      EXPECT_NEAR(r, r0, 1e-3);
      EXPECT_GE(r, 0.85 * fibres::core * 1.0 - 1e-4);  // in the outer shell of the ply
      EXPECT_LE(r, 1.0 + 1e-4);
      if (k > 0) {
        const glm::vec3 q = lines.positions[f * per_fibre + k - 1];
        double d = std::atan2(p.z, p.y) - std::atan2(q.z, q.y);
        if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
        if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
        turned += d;
      }
    }
    EXPECT_NEAR(std::abs(turned) / (2 * std::numbers::pi), 20.0, 0.3) << "fibre " << f;
  }
}

TEST(Fibres, MigrationSwingsAFibreInAndOut) {
  Yarn yarn;
  yarn.color = "#d9c8a9";
  yarn.diameter = 2.0;
  yarn.fibres.plies = 1;
  yarn.fibres.fibres_per_ply = 3;
  yarn.fibres.migration = 0.4;
  yarn.fibres.hairs = yarn.fibres.loops = 0.0;
  const std::vector<curves::CurvePiece> pieces{straight(yarn)};
  const mesh::Mesh m = fibres::build_mesh(std::vector<Yarn>{yarn}, pieces, 12, 1);
  const mesh::Primitive& lines = m.primitives[1];
  double lo = 1e9, hi = 0.0;
  for (std::size_t k = 0; k < lines.positions.size() / 3; ++k) {
    const double r = std::hypot(lines.positions[k].y, lines.positions[k].z);
    lo = std::min(lo, r), hi = std::max(hi, r);
  }
  EXPECT_NEAR(lo / hi, 0.4, 0.02);  // in to 0.4 of its rest radius and back out
}

CompileOptions with_fibres(int threads) {
  CompileOptions o;
  o.threads = threads;
  o.fibres = true;
  return o;
}

// How far each line vertex lies from the yarn's centreline, as a fraction of its radius.
std::vector<double> reach(const Pattern& p) {
  const Fabric f = compile(p, with_fibres(2));
  std::vector<double> out;
  const double radius = 0.5 * p.yarns[0].diameter;
  for (const mesh::Primitive& prim : f.mesh.primitives) {
    if (prim.mode != mesh::Mode::lines) continue;
    for (const glm::vec3& v : prim.positions) {
      double best = 1e9;
      for (const auto& piece : f.pieces)
        for (const auto& o : piece.frames.origin) best = std::min(best, glm::length(glm::dvec3(v) - o));
      out.push_back(best / radius);
    }
  }
  return out;
}

TEST(Fibres, FlyawaysReachAsFarAsTheHaloAndMohairIsFuzzier) {
  const auto beyond = [](const std::vector<double>& r, double at) {
    return static_cast<double>(std::count_if(r.begin(), r.end(), [&](double x) { return x > at; })) / static_cast<double>(r.size());
  };
  const yarn::FibreModel wool = yarn::fibre_preset("wool"), mohair = yarn::fibre_preset("mohair");
  const std::vector<double> w = reach(run("fibre = \"wool\"")), m = reach(run("fibre = \"mohair\""));
  // The centreline's samples are a few tenths of a mm apart: allow that much.
  const double slack = 0.25;
  EXPECT_LE(*std::max_element(w.begin(), w.end()), 1.0 + wool.halo + slack);
  EXPECT_LE(*std::max_element(m.begin(), m.end()), 1.0 + mohair.halo + slack);
  EXPECT_GT(*std::max_element(m.begin(), m.end()), 1.0 + 0.5 * mohair.halo);
  EXPECT_GT(beyond(m, 1.5), 5.0 * beyond(w, 1.5));  // a halo
  const std::vector<double> smooth = reach(run("fibre = \"wool\", hairs = 0, loops = 0"));
  EXPECT_LE(*std::max_element(smooth.begin(), smooth.end()), 1.0 + slack);
}

TEST(Fibres, TheSameBytesForAnyThreadCountAndValidGltf) {
  const Pattern p = run("fibre = \"alpaca\", colors = { {\"#aa3322\", 3}, {\"#eeeeee\", 2} }");
  const Fabric one = compile(p, with_fibres(1));
  const Fabric two = compile(p, with_fibres(2));
  const std::string a = writers::glb(one.mesh, "knitc test"), b = writers::glb(two.mesh, "knitc test");
  EXPECT_EQ(a, b);
  EXPECT_NE(one.mesh_choice.find("fibres"), std::string::npos) << one.mesh_choice;
  test::write_text(test::glb_dir() / "fibres.glb", a);  // the validator test checks it
}

}  // namespace
}  // namespace knitc
