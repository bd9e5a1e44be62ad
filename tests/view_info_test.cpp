// The live view's data (view/info.hpp): what the page names and counts.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compile.hpp"
#include "measure/measure.hpp"
#include "runtime.hpp"
#include "support.hpp"
#include "view/info.hpp"

namespace knitc {
namespace {

const char* colourwork = R"(pattern {
  name = "two colours",
  gauge = { stitches = 22, rows = 30 },
  yarns = { A = { weight = "dk", color = "#d9c8a9" }, B = { weight = "dk", color = "#2a4d69", metres_per_100g = 200 } },
  knitting = "flat",
}
cast_on(12)
for _ = 1, 3 do
  row "k"
  row "p"
end
course { "k", rep = 12, yarn = "B" }
row("p", { yarn = "B" })
row "k"
bind_off()
)";

TEST(ViewInfo, YarnPerColourAgreesWithTheSnapshotsLengths) {
  const auto run = runtime::run_pattern(colourwork, "two.lua");
  CompileOptions options;
  options.relax = true;
  const Fabric fabric = compile(run.pattern, options);
  const auto measures = measure::measure(run.pattern, fabric.layout, fabric.pieces);
  const auto info = nlohmann::json::parse(view::fabric_info(run.pattern, fabric));
  const auto& yarns = info["figures"]["yarns"];
  ASSERT_EQ(yarns.size(), 2u);
  for (std::size_t y = 0; y < 2; ++y) {
    const double metres = yarns[y]["metres"].get<double>();
    const double snapshot_mm = measures.yarn_length[y];
    EXPECT_NEAR(metres * 1000.0, snapshot_mm, 0.01 * snapshot_mm) << yarns[y]["id"];
    EXPECT_GT(metres, 0.0);
  }
  // Grams from the weight per length: A a DK's typical 230 m per 100 g, B its label's 200.
  EXPECT_NEAR(yarns[0]["grams"].get<double>(), yarns[0]["metres"].get<double>() * 100.0 / 230.0, 1e-3);
  EXPECT_NEAR(yarns[1]["grams"].get<double>(), yarns[1]["metres"].get<double>() * 100.0 / 200.0, 1e-3);
}

TEST(ViewInfo, EveryLoopOfARowBelongsToItsChartCell) {
  const auto run = runtime::run_pattern(colourwork, "two.lua");
  CompileOptions options;
  options.relax = false;
  const Fabric fabric = compile(run.pattern, options);
  const auto info = nlohmann::json::parse(view::fabric_info(run.pattern, fabric));
  ASSERT_EQ(info["rows"].size(), run.pattern.courses.size());
  // Row 7 is the first in B, worked at line 12 of the script; each cell one loop, in B.
  const auto& row7 = info["rows"][6];
  EXPECT_EQ(row7["line"], 12);
  EXPECT_EQ(row7["file"], "two.lua");
  ASSERT_EQ(row7["cells"].size(), 12u);
  for (std::size_t k = 0; k < 12; ++k) {
    const auto& cell = row7["cells"][k];
    EXPECT_EQ(cell["yarn"], "B");
    EXPECT_EQ(cell["abbreviation"], "k");
    EXPECT_EQ(cell["name"], "knit");
    ASSERT_EQ(cell["loops"].size(), 1u);
    const auto loop = cell["loops"][0].get<std::size_t>();
    EXPECT_EQ(info["loops"][loop][0], 7);  // its course
    EXPECT_EQ(info["loops"][loop][1], k);  // its cell
  }
  EXPECT_EQ(info["figures"]["loops"], fabric.layout.loops.size());
}

}  // namespace
}  // namespace knitc
