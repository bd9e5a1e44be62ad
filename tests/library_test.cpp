// The pattern library: every fabric in patterns/ compiles, every yarn tube of it is
// closed and two-manifold, and its .glb goes to the validator.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "measure/measure.hpp"
#include "support.hpp"
#include "topology.hpp"
#include "writers/writers.hpp"

namespace knitc {
namespace {

std::vector<std::string> library() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(KNITC_SOURCE_DIR) + "/patterns")) {
    if (entry.path().extension() == ".lua") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class Library : public testing::TestWithParam<std::string> {};

TEST_P(Library, CompilesToClosedTwoManifoldTubes) {
  const std::string path = std::string(KNITC_SOURCE_DIR) + "/patterns/" + GetParam() + ".lua";
  const Pattern pattern = runtime::run_pattern_file(path).pattern;
  CompileOptions o;
  o.sides = 6;
  o.chord_tolerance = 0.05;
  const Fabric fabric = compile(pattern, o);
  ASSERT_FALSE(fabric.pieces.empty());
  // The compiled mesh itself: each yarn's primitive is a set of closed, two-manifold,
  // outward-facing tubes (genus 0: V - E + F = 2 for each), at least one per piece. (The
  // test once swept each strand again with the sides rule copied from the compiler.)
  std::size_t tubes = 0;
  for (const mesh::Primitive& prim : fabric.mesh.primitives) {
    ASSERT_EQ(prim.mode, mesh::Mode::triangles);
    const test::TopologyReport t = test::topology(prim);
    EXPECT_EQ(t.non_manifold_edges, 0u) << "material " << prim.material;
    EXPECT_EQ(t.inconsistent_edges, 0u);
    EXPECT_EQ(static_cast<long long>(t.welded_vertices) - static_cast<long long>(t.edges) + static_cast<long long>(t.triangles),
              2 * static_cast<long long>(t.components));
    EXPECT_GT(t.least_component_volume, 0.0);  // every tube faces out
    tubes += t.components;
  }
  EXPECT_GE(tubes, fabric.pieces.size());
  // Every loop of the fabric belongs to exactly one piece of yarn in the smooth model.
  std::vector<int> owners(fabric.layout.loops.size(), 0);
  for (const CurvePiece& piece : fabric.pieces)
    for (int loop : piece.path.loops) ++owners[loop];
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
  // The sanity figures are finite and the overlap is the seed geometry's, not a tangle.
  const auto m = measure::measure(pattern, fabric.layout, fabric.pieces);
  EXPECT_GT(m.deepest_penetration, 0.5);
  EXPECT_LT(m.deepest_penetration, 1.05);
  EXPECT_LT(m.largest_frame_turn, 45.0);
  std::ofstream out(test::glb_dir() / ("library_" + GetParam() + ".glb"), std::ios::binary);
  writers::write_glb(fabric.mesh, "knitc test", out);
}

INSTANTIATE_TEST_SUITE_P(Patterns, Library, testing::ValuesIn(library()),
                         [](const testing::TestParamInfo<std::string>& param) { return param.param; });

}  // namespace
}  // namespace knitc
