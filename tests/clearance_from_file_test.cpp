// Clearance measured from the centreline JSON alone, as anyone reading the file would:
// a second implementation (its own grid, its own fill) beside measure::measure, which
// works from the compiler's data. Where both can speak they must agree; the file's own
// core diameters then give the clearance of the cores.
#include <gtest/gtest.h>

#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "compile.hpp"
#include "measure/measure.hpp"
#include "support.hpp"
#include "writers/writers.hpp"
#include "yarn/size.hpp"

namespace knitc {
namespace {

struct Clearance {
  double free = 0.0;  // deepest (r_a + r_b - distance) over the thicker free diameter; 0: none
  double core = 0.0;  // the same with the core radii, over the thicker core diameter
};

struct FilePoint {
  glm::dvec3 at;
  int yarn = 0, piece = 0;
  double along = 0.0;  // mm along its piece
};

// Pairs of points of different pieces, or of one piece more than two free diameters
// apart along it (the rule measure::FabricMeasures states), each piece's polyline filled
// in to a quarter of the thinnest core apart.
Clearance clearance_of(const nlohmann::json& doc) {
  std::vector<double> free_d, core_d;
  std::vector<FilePoint> points;
  double thinnest = 1e9, widest = 0.0;
  for (const auto& y : doc["yarns"]) {
    free_d.push_back(y["free_diameter"].get<double>());
    core_d.push_back(y["core_diameter"].get<double>());
    thinnest = std::min(thinnest, core_d.back());
    widest = std::max(widest, free_d.back());
  }
  const double step = 0.25 * thinnest;
  int piece_id = 0;
  for (std::size_t y = 0; y < doc["yarns"].size(); ++y) {
    const auto& yarn = doc["yarns"][y];
    for (const auto& piece : yarn["pieces"]) {
      const std::size_t first = piece[0], count = piece[1];
      double along = 0.0;
      glm::dvec3 previous{};
      for (std::size_t k = first; k < first + count; ++k) {
        const glm::dvec3 p{yarn["points"][k][0].get<double>(), yarn["points"][k][1].get<double>(),
                           yarn["points"][k][2].get<double>()};
        if (k > first) {
          const double length = glm::distance(previous, p);
          const int fill = static_cast<int>(std::ceil(length / step));
          for (int f = 1; f < fill; ++f) {
            const double t = static_cast<double>(f) / fill;
            points.push_back({previous + t * (p - previous), static_cast<int>(y), piece_id, along + t * length});
          }
          along += length;
        }
        points.push_back({p, static_cast<int>(y), piece_id, along});
        previous = p;
      }
      ++piece_id;
    }
  }
  auto key = [&](const glm::dvec3& p, int dx, int dy, int dz) {
    const auto cell = [&](double v, int d) { return static_cast<long long>(std::floor(v / widest)) + d; };
    return (cell(p.x, dx) * 73856093LL) ^ (cell(p.y, dy) * 19349663LL) ^ (cell(p.z, dz) * 83492791LL);
  };
  std::unordered_map<long long, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < points.size(); ++i) grid[key(points[i].at, 0, 0, 0)].push_back(i);
  Clearance c;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const FilePoint& a = points[i];
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto cell = grid.find(key(a.at, dx, dy, dz));
          if (cell == grid.end()) continue;
          for (std::size_t j : cell->second) {
            if (j <= i) continue;
            const FilePoint& b = points[j];
            if (a.piece == b.piece && std::abs(a.along - b.along) <= 2.0 * free_d[static_cast<std::size_t>(a.yarn)]) continue;
            const double distance = glm::distance(a.at, b.at);
            const auto ya = static_cast<std::size_t>(a.yarn), yb = static_cast<std::size_t>(b.yarn);
            c.free = std::max(c.free, (0.5 * (free_d[ya] + free_d[yb]) - distance) / std::max(free_d[ya], free_d[yb]));
            c.core = std::max(c.core, (0.5 * (core_d[ya] + core_d[yb]) - distance) / std::max(core_d[ya], core_d[yb]));
          }
        }
  }
  return c;
}

struct Measured {
  Clearance file;
  double penetration = 0.0, core_penetration = 0.0;  // measure::measure's, from the compiler's data
};

Measured measured(const std::string& body, bool relax) {
  const std::string source =
      "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
      "knitting = \"flat\" }\n" + body;
  const Pattern p = runtime::run_pattern(source, "t.lua").pattern;
  CompileOptions options;
  options.relax = relax;
  const Fabric f = compile(p, options);
  const auto doc = nlohmann::json::parse(writers::centreline_json(p, f, yarn_paths::LoopModel::smooth));
  const auto m = measure::measure(p, f.layout, f.pieces);
  return {clearance_of(doc), m.deepest_penetration, m.deepest_core_penetration};
}

// The file and the compiler agree on how deep the tubes overlap, unrelaxed and relaxed.
// The compiler fills the samples to a quarter free diameter apart, the file's reader to a
// quarter core (about an eighth): the finer fill finds the closest approach as deep or
// deeper, by what the coarser fill misses between its points: a few hundredths of d
// (0.011 d at most on these fabrics, 2026-12-02).
TEST(ClearanceFromFile, AgreesWithTheCompilersMeasure) {
  for (const char* body : {"cast_on(6)\nrows(6, \"k\")\n", "cast_on(8)\nrows(6, \"k1, p1\")\n"}) {
    for (bool relax : {false, true}) {
      const Measured m = measured(body, relax);
      EXPECT_GE(m.file.free, m.penetration - 0.005) << body << (relax ? " relaxed" : "");
      EXPECT_LE(m.file.free, m.penetration + 0.03) << body << (relax ? " relaxed" : "");
      EXPECT_GE(m.file.core, m.core_penetration - 0.005) << body << (relax ? " relaxed" : "");
      EXPECT_LE(m.file.core, m.core_penetration + 0.06) << body << (relax ? " relaxed" : "");
    }
  }
}

// At the seed paper's proportions the layout's interlocks overlap by some 0.85 of the
// free diameter, and so the cores too; relaxed, the cores clear (within the 5% of
// a core diameter) and the shells between core and free surface are pressed, never past
// their whole depth.
TEST(ClearanceFromFile, TheCoresClearAndTheShellsPress) {
  const Measured off = measured("cast_on(6)\nrows(6, \"k\")\n", false);
  EXPECT_GT(off.file.free, 0.8);
  EXPECT_GT(off.file.core, 0.5);
  const Measured on = measured("cast_on(6)\nrows(6, \"k\")\n", true);
  EXPECT_LE(on.file.core, 0.05);
  EXPECT_LT(on.file.free, 1.0 - 1.0 / yarn::free_per_core);
}

// Samples piled up in one place (a curve through data points a nanometre apart was once
// sampled 3 million times in one span) are measured as one point: the search compares a
// cell's points pair by pair, so 200,000 in a cell took minutes. The pile-up changes
// nothing measured.
TEST(ClearanceFromFile, SamplesPiledUpInOnePlaceAreMeasuredOnce) {
  const Pattern p =
      runtime::run_pattern("pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 2 }, yarns = { A = { diameter = 1 } }, "
                           "knitting = \"flat\" }\ncast_on(6)\nrows(6, \"k\")\n",
                           "t.lua")
          .pattern;
  const Fabric f = compile(p, CompileOptions{});
  const auto before = measure::measure(p, f.layout, f.pieces);
  std::vector<curves::CurvePiece> piled = f.pieces;
  curves::CurvePiece& c = piled[0];
  const std::size_t s = c.samples.size() / 2, copies = 200000;
  auto pile = [&](auto& v) { v.insert(v.begin() + static_cast<std::ptrdiff_t>(s), copies, v[s]); };
  pile(c.samples), pile(c.arc_length), pile(c.frames.origin), pile(c.frames.tangent), pile(c.frames.normal), pile(c.frames.binormal);
  for (std::size_t k = 0; k < copies; ++k) c.frames.origin[s + k].x += 1e-9 * static_cast<double>(k);  // all but equal
  const auto after = measure::measure(p, f.layout, piled);
  EXPECT_EQ(after.deepest_penetration, before.deepest_penetration);
  EXPECT_EQ(after.deepest_core_penetration, before.deepest_core_penetration);
}

}  // namespace
}  // namespace knitc
