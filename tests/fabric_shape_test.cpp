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
  CompileOptions o = test::centrelines(true);
  o.relaxation.boundary = boundary;
  return o;
}

// A jersey swatch relaxed within `boundary`, its inner loops' shape (none if it did not
// settle).
measure::LoopShape relaxed_jersey_shape(int stitches, int rows, relax::Boundary boundary) {
  const Pattern pattern = test::jersey(stitches, rows);
  const Fabric f = compile(pattern, relaxed_centrelines(boundary));
  EXPECT_LT(f.relaxation.iterations, relax::Options{}.max_iterations) << "did not settle";
  if (f.relaxation.iterations >= relax::Options{}.max_iterations) return {};
  return measure::loop_shape(f.layout, f.pieces);
}

// Munden's and Knapton's band (below), each factor 5% past it.
void expect_real_jersey(const measure::LoopShape& shape) {
  EXPECT_GE(shape.kc, 0.95 * 5.0) << "l " << shape.loop_length << ", course spacing " << shape.course_spacing;
  EXPECT_LE(shape.kc, 1.05 * 5.5);
  EXPECT_GE(shape.kw, 0.95 * 3.8) << "l " << shape.loop_length << ", wale spacing " << shape.wale_spacing;
  EXPECT_LE(shape.kw, 1.05 * 4.2);
  EXPECT_GE(shape.kc / shape.kw, 1.2);
  EXPECT_LE(shape.kc / shape.kw, 1.45);
}

// Plain jersey, its loop length fixed by the layout (W 4, H 4.2, T 2 mm, a 1 mm yarn: l
// about 15.6 mm), takes a relaxed state of real jersey: kc = l x courses per mm and kw =
// l x wales per mm from 5% under Munden's dry-relaxed 5.0 and 3.8 to 5% over Knapton's
// fully relaxed 5.5 and 4.2 (Munden 1959, as tabulated by Spencer; Knapton 1968), and a
// loop taller than wide as kc / kw 1.2 to 1.45 say. (The relaxation has no friction to
// hold a loop short of its rest, as a dry fabric's does: it lands between dry and wet,
// kc 5.26, 5.2% over the dry figure; docs/relaxation.md.) A swatch with free edges, as a
// designer compiles it (relaxed by its repeat), measured on its inner loops.
TEST(FabricShape, JerseyTakesARelaxedShapeOfRealJersey) {
  const auto shape = relaxed_jersey_shape(16, 20, relax::Boundary::free);
  EXPECT_GT(shape.loops, 100u);
  expect_real_jersey(shape);
  RecordProperty("kc", std::to_string(shape.kc));
  RecordProperty("kw", std::to_string(shape.kw));
}

// A periodic repeat of the same jersey (endless across and up, its size free) finds a
// shape in the same band: its size follows the strain the contacts, lengths and bending
// ask for.
TEST(FabricShape, AJerseyRepeatTakesTheSameShape) {
  const auto shape = relaxed_jersey_shape(8, 8, relax::Boundary::periodic);
  EXPECT_GT(shape.loops, 10u);
  expect_real_jersey(shape);
}

}  // namespace
}  // namespace knitc

