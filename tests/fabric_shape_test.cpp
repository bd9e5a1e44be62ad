// The relaxed fabric's shape against published measurements of real fabric (issue 16;
// docs/relaxation.md, "Shape against real fabric", gives every figure beside its source).
// Only the bands the relaxation meets are here; the ones it misses are in that table.
#include <gtest/gtest.h>

#include "compile.hpp"
#include "measure/measure.hpp"
#include "support.hpp"

namespace knitc {
namespace {

CompileOptions relaxed_centrelines(relax::Boundary boundary) {
  CompileOptions o;
  o.view = View::centreline;
  o.chord_tolerance = 0.05;
  o.relax = true;
  o.relaxation.boundary = boundary;
  return o;
}

// Plain jersey, its loop length fixed by the layout (W 4, H 4.2, T 2 mm, a 1 mm yarn: l
// about 15.6 mm): Munden's dry-relaxed kc = l x courses per mm about 5.0 and kw = l x
// wales per mm about 3.8 (Munden 1959, as tabulated by Spencer), within 5%, and a loop
// taller than wide as kc / kw 1.2 to 1.45 say. A swatch with free edges, as a designer
// compiles it, measured on its inner loops.
TEST(FabricShape, JerseyTakesMundensDryRelaxedShape) {
  const Pattern pattern = test::jersey(16, 20);
  const Fabric f = compile(pattern, relaxed_centrelines(relax::Boundary::free));
  ASSERT_LT(f.relaxation.iterations, relax::Options{}.max_iterations) << "did not settle";
  const auto shape = measure::loop_shape(f.layout, f.pieces);
  ASSERT_GT(shape.loops, 100u);
  EXPECT_NEAR(shape.kc, 5.0, 0.05 * 5.0) << "l " << shape.loop_length << ", course spacing " << shape.course_spacing;
  EXPECT_NEAR(shape.kw, 3.8, 0.05 * 3.8) << "l " << shape.loop_length << ", wale spacing " << shape.wale_spacing;
  EXPECT_GE(shape.kc / shape.kw, 1.2);
  EXPECT_LE(shape.kc / shape.kw, 1.45);
  RecordProperty("kc", std::to_string(shape.kc));
  RecordProperty("kw", std::to_string(shape.kw));
}

// A periodic repeat of the same jersey (endless across and up, its size free) finds the
// same shape as the swatch's inner loops, within the same band: its size follows the
// strain the contacts, lengths and bending ask for.
TEST(FabricShape, AJerseyRepeatTakesTheSameShape) {
  const Pattern pattern = test::jersey(8, 8);
  const Fabric f = compile(pattern, relaxed_centrelines(relax::Boundary::periodic));
  ASSERT_LT(f.relaxation.iterations, relax::Options{}.max_iterations) << "did not settle";
  const auto shape = measure::loop_shape(f.layout, f.pieces);
  ASSERT_GT(shape.loops, 10u);
  EXPECT_NEAR(shape.kc, 5.0, 0.05 * 5.0);
  EXPECT_NEAR(shape.kw, 3.8, 0.05 * 3.8);
  EXPECT_GE(shape.kc / shape.kw, 1.2);
  EXPECT_LE(shape.kc / shape.kw, 1.45);
}

}  // namespace
}  // namespace knitc
