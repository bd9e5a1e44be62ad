// The compiler's stages on one course of the default jersey (W 4, H 4.2, T 2, d 1 mm),
// for finding where time goes; `knitc bench` times the whole job.
#include <benchmark/benchmark.h>

#include "compile.hpp"
#include "layout/layout.hpp"
#include "writers/writers.hpp"

namespace {

using namespace knitc;

Pattern jersey(int wales, int courses) {
  Pattern p;
  p.name = "bench";
  p.yarns.push_back({"A", 1.0, "#d9c8a9"});
  p.cast_on = wales;
  Course c;
  c.ops.assign(static_cast<std::size_t>(wales), Op{stitch_id("k"), 0});
  p.courses.assign(static_cast<std::size_t>(courses), c);
  return p;
}

std::vector<glm::dvec3> course_points(int wales) {
  const auto layout = layout::lay_out(jersey(wales, 1));
  return yarn_paths::trace(layout, yarn_paths::LoopModel::smooth)[0].data_points;
}

void Interpolate(benchmark::State& state) {
  const auto q = course_points(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(nurbs::interpolate(q));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(Interpolate)->Arg(30)->Arg(150)->Arg(300);

void Sample(benchmark::State& state) {
  const auto curve = nurbs::interpolate(course_points(static_cast<int>(state.range(0)))).curve;
  for (auto _ : state) benchmark::DoNotOptimize(sweep::sample_parameters(curve, 0.0, 1.0, 0.01, 0.5));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(Sample)->Arg(30)->Arg(150);

void Frames(benchmark::State& state) {
  const auto curve = nurbs::interpolate(course_points(static_cast<int>(state.range(0)))).curve;
  const auto u = sweep::sample_parameters(curve, 0.0, 1.0, 0.01, 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(sweep::frames(curve, u, sweep::FrameKind::rotation_minimising));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(Frames)->Arg(30)->Arg(150);

void Tubes(benchmark::State& state) {
  const auto curve = nurbs::interpolate(course_points(static_cast<int>(state.range(0)))).curve;
  const auto u = sweep::sample_parameters(curve, 0.0, 1.0, 0.01, 0.5);
  const auto f = sweep::frames(curve, u, sweep::FrameKind::rotation_minimising);
  std::vector<double> s(u.size());
  for (std::size_t i = 1; i < u.size(); ++i) s[i] = s[i - 1] + nurbs::segment_length(curve, u[i - 1], u[i]);
  const auto strands = sweep::strands(f, s, sweep::CrossSection{});
  for (auto _ : state) {
    mesh::Primitive prim;
    sweep::append_tubes(strands, s, 12, prim);
    benchmark::DoNotOptimize(prim.indices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(Tubes)->Arg(30)->Arg(150);

void CompileSwatch(benchmark::State& state) {
  const Pattern p = jersey(static_cast<int>(state.range(0)), static_cast<int>(state.range(0)));
  CompileOptions o;
  o.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(compile(p, o).mesh.primitives.size());
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(CompileSwatch)->Arg(30)->Unit(benchmark::kMillisecond);

void WriteGlb(benchmark::State& state) {
  const Fabric f = compile(jersey(30, 30), CompileOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(writers::glb(f.mesh, "bench").size());
}
BENCHMARK(WriteGlb)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
