// A yarn's two diameters from what a designer gives (compiler/yarn/size.hpp), and the
// pattern language reading them.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "compile.hpp"
#include "fields.hpp"
#include "support.hpp"
#include "writers/writers.hpp"
#include "yarn/size.hpp"

namespace knitc {
namespace {

Yarn yarn_of(const std::string& fields) {
  const std::string source = "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { " + fields +
                             " } } }\ncast_on(4)\nrow \"k\"\n";
  return runtime::run_pattern(source, "t.lua").pattern.yarns.at(0);
}

TEST(YarnSize, WrapsPerInchGiveTheLooseWidthAndTheCompactCore) {
  for (double wpi : {4.0, 10.5, 22.0, 35.0}) {
    const yarn::Size s = yarn::from_wpi(wpi);
    EXPECT_DOUBLE_EQ(s.free_diameter, 0.85 * 25.4 / wpi);
    // The compact core: 1/2 to 1/2.5 of 25.4 / WPI.
    EXPECT_GE(s.core_diameter, 25.4 / wpi / 2.5);
    EXPECT_LE(s.core_diameter, 25.4 / wpi / 2.0);
    EXPECT_NEAR(s.free_diameter / s.core_diameter, yarn::free_per_core, 1e-12);
  }
}

// The two routes to a core agree on typical wool yarns: grams per length as yarn labels
// give it (fingering about 400 m per 100 g, DK 230, worsted 200, bulky 120) against wraps
// per inch in each weight's band.
TEST(YarnSize, TexAndWrapsAgreeOnTypicalWools) {
  const double wool = yarn::find_fibre("wool")->density;
  const std::pair<double, double> labels[] = {{250.0, 16.0}, {435.0, 12.0}, {500.0, 10.0}, {833.0, 8.0}};
  for (const auto& [tex, wpi] : labels) {
    const double ratio = yarn::from_tex(tex, wool).core_diameter / yarn::from_wpi(wpi).core_diameter;
    EXPECT_NEAR(ratio, 1.0, 0.10) << tex << " tex, " << wpi << " WPI";
  }
  // A 500 tex worsted wool: a core of about 1.04 mm.
  EXPECT_NEAR(yarn::from_tex(500.0, wool).core_diameter, 1.039, 0.002);
  // Four times the grams per km: twice the diameter. A denser fibre: a thinner core.
  EXPECT_NEAR(yarn::from_tex(2000.0, wool).core_diameter, 2.0 * yarn::from_tex(500.0, wool).core_diameter, 1e-9);
  EXPECT_LT(yarn::from_tex(500.0, yarn::find_fibre("cotton")->density).core_diameter,
            yarn::from_tex(500.0, wool).core_diameter);
}

// The limits of wpi, tex and core_diameter keep every free diameter within diameter's
// own limit, for every fibre.
TEST(YarnSize, EveryWayStaysWithinTheDiametersLimit) {
  const double most = runtime::field("yarn", "diameter").hi;
  EXPECT_LE(yarn::from_wpi(runtime::field("yarn", "wpi").lo).free_diameter, most);
  EXPECT_LE(yarn::from_core_diameter(runtime::field("yarn", "core_diameter").hi).free_diameter, most);
  for (const yarn::Fibre& f : yarn::fibres())
    EXPECT_LE(yarn::from_tex(runtime::field("yarn", "tex").hi, f.density).free_diameter, most) << f.name;
}

TEST(YarnSize, ThePatternLanguageReadsEveryWay) {
  const Yarn dk = yarn_of("weight = \"DK\"");
  EXPECT_DOUBLE_EQ(dk.diameter, yarn::from_wpi(13.0).free_diameter);
  EXPECT_DOUBLE_EQ(dk.core_diameter, yarn::from_wpi(13.0).core_diameter);
  const Yarn wpi = yarn_of("wpi = 13");
  EXPECT_EQ(wpi.diameter, dk.diameter);
  EXPECT_EQ(wpi.core_diameter, dk.core_diameter);
  const Yarn tex = yarn_of("tex = 250, fibre = \"cotton\"");
  EXPECT_DOUBLE_EQ(tex.core_diameter, yarn::from_tex(250.0, 1.52).core_diameter);
  EXPECT_DOUBLE_EQ(tex.diameter, tex.core_diameter * yarn::free_per_core);
  const Yarn plain = yarn_of("diameter = 1.5");
  EXPECT_DOUBLE_EQ(plain.diameter, 1.5);
  EXPECT_DOUBLE_EQ(plain.core_diameter, 1.5 / yarn::free_per_core);
  const Yarn both = yarn_of("diameter = 1.5, core_diameter = 1.0");
  EXPECT_DOUBLE_EQ(both.diameter, 1.5);
  EXPECT_DOUBLE_EQ(both.core_diameter, 1.0);
  const Yarn core = yarn_of("core_diameter = 0.8");
  EXPECT_DOUBLE_EQ(core.diameter, 0.8 * yarn::free_per_core);
  EXPECT_DOUBLE_EQ(core.core_diameter, 0.8);
}

TEST(YarnSize, TheCentrelineFileRecordsBothDiameters) {
  const std::string source =
      "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, core_diameter = 0.7 }, "
      "B = { weight = \"dk\" } } }\n"
      "cast_on(4)\nrows(2, \"k\")\nrow \"k4 B\"\nrow \"k2, k2 B\"\n";
  const Pattern p = runtime::run_pattern(source, "t.lua").pattern;
  const Fabric f = compile(p, {});
  const auto doc = nlohmann::json::parse(writers::centreline_json(p, f, yarn_paths::LoopModel::smooth));
  EXPECT_DOUBLE_EQ(doc["yarns"][0]["free_diameter"].get<double>(), 1.2);
  EXPECT_DOUBLE_EQ(doc["yarns"][0]["core_diameter"].get<double>(), 0.7);
  // Each loop's stretch is a range of its yarn's points: the very samples it lists.
  ASSERT_EQ(doc["yarns"].size(), 2u);
  for (const auto& loop : doc["loops"]) {
    const auto& points = doc["yarns"][loop["yarn"] == "A" ? 0 : 1]["points"];
    const std::size_t first = loop["points"][0], last = loop["points"][1];
    ASSERT_LE(first, last);
    ASSERT_LT(last, points.size());
    ASSERT_EQ(loop["samples"].size(), last - first + 1);
    for (std::size_t k = first; k <= last; ++k) EXPECT_EQ(loop["samples"][k - first], points[k]);
  }
}

}  // namespace
}  // namespace knitc
