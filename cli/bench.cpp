#include "bench.hpp"

#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <fstream>
#include <string_view>
#include <vector>

#include <fmt/core.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include "runtime.hpp"
#include "tiles/tiles.hpp"
#include "writers/writers.hpp"

namespace knitc::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double peak_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// A memcpy of `bytes`, the best of three: what writing the output to memory costs.
double memcpy_seconds(std::size_t bytes) {
  std::vector<char> from(bytes, 1), to(bytes, 0);
  double best = 1e30;
  for (int i = 0; i < 3; ++i) {
    const auto t0 = Clock::now();
    std::memcpy(to.data(), from.data(), bytes);
    best = std::min(best, seconds_since(t0));
    if (to[bytes / 2] != 1) return -1.0;  // keeps the copy from being optimised away
  }
  return best;
}

// A memcpy of `bytes` into memory just allocated, never touched: what any step that
// writes a new array of that size pays at least, its pages faulted in and zeroed by the
// kernel (on a virtual machine, many times the copy itself).
double fresh_memcpy_seconds(std::size_t bytes) {
  std::vector<char> from(bytes, 1);
  const auto t0 = Clock::now();
  std::unique_ptr<char[]> to(new char[bytes]);
  std::memcpy(to.get(), from.data(), bytes);
  const double took = seconds_since(t0);
  return to[bytes / 2] == 1 ? took : -1.0;
}

}  // namespace

int bench(int wales, int courses, const CompileOptions& options, bool header, bool flat) {
  const std::string source =
      flat ? fmt::format("pattern {{ name = \"bench\", gauge = {{ loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }},\n"
                         "  yarns = {{ A = {{ diameter = 1.0, color = \"#d9c8a9\" }} }}, knitting = \"flat\" }}\ncast_on({})\n"
                         "for i = 1, {} do row(i % 2 == 1 and \"k\" or \"p\") end\nbind_off()\n",
                         wales, courses)
           : fmt::format("pattern {{ name = \"bench\", gauge = {{ loop_width = 4.0, loop_height = 4.2, thickness = 2.0 }},\n"
                         "  yarns = {{ A = {{ diameter = 1.0, color = \"#d9c8a9\" }} }} }}\ncast_on({})\nrows({}, \"k\")\n",
                         wales, courses);
  const auto start = Clock::now();
  const Pattern pattern = runtime::run_pattern(source, "bench.lua").pattern;
  const double script = seconds_since(start);
  const auto t1 = Clock::now();
  // The relaxation's own time, told by its progress (the compiler keeps no clocks).
  CompileOptions timed = options;
  Clock::time_point relax_start;
  double relax_seconds = 0.0;
  timed.progress = [&](const char* stage, double fraction) {
    if (std::string_view(stage) != "relax") return;
    if (fraction == 0.0) relax_start = Clock::now();
    else relax_seconds = seconds_since(relax_start);
  };
  Fabric fabric = compile(pattern, timed);
  const double mesh = seconds_since(t1);
  // A folder of its own (mkdtemp: a name nobody can plant a link at) for the one file.
  std::string folder = (std::filesystem::temp_directory_path() / "knitc-bench-XXXXXX").string();
  if (::mkdtemp(folder.data()) == nullptr) throw writers::OutputError("cannot make a folder for the bench's file in " + folder);
  struct RemoveFolder {
    const std::string& folder;
    ~RemoveFolder() {
      std::error_code ec;
      std::filesystem::remove_all(folder, ec);
    }
  } remove_folder{folder};
  const auto path = std::filesystem::path(folder) / "bench.glb";
  const auto t2 = Clock::now();
  writers::write_files(std::vector<writers::OutputFile>{
      {path.string(), [&](std::ostream& out) {
         // As `knitc build` writes it: an instanced fabric compressed.
         writers::write_glb(fabric.mesh, "knitc bench", out, {fabric.instanced, fabric.instanced, options.threads});
       }}});
  const double write = seconds_since(t2);
  const double total = seconds_since(start);
  const double peak = peak_mib();  // before the memcpy below, which holds two more copies
  const auto bytes = std::filesystem::file_size(path);
  const std::size_t triangles = tiles::drawn(fabric.mesh).triangles;
  const bool instanced = fabric.instanced;
  const Density density = fabric.density;
  const double loops = static_cast<double>(fabric.layout.loops.size());
  const bool relaxed = fabric.relaxed;
  const int relax_iterations = fabric.relaxation.iterations;
  const bool flattened = options.instancing == Instancing::flatten && fabric.mesh.instanced.empty() &&
                         fabric.mesh_choice.find("every instance") != std::string::npos;
  fabric = Fabric{};  // freed before the timings below, which each start with the memory the job left
  // --flatten's own step, timed against a memcpy of its bytes below: the instances written
  // out (tiles::flatten) from the instanced mesh it was given.
  double flatten_seconds = -1.0;
  std::size_t flatten_bytes = 0;
  if (flattened) {
    CompileOptions again = options;
    again.instancing = Instancing::instance;
    again.progress = nullptr;
    const Fabric tiled = compile(pattern, again);
    const auto t3 = Clock::now();
    const mesh::Mesh flat_mesh = tiles::flatten(tiled.mesh, options.threads);
    flatten_seconds = seconds_since(t3);
    for (const auto& p : flat_mesh.primitives)
      flatten_bytes += p.positions.size() * 32 + p.indices.size() * 4;  // position, normal, uv; indices
  }
  const double copy = memcpy_seconds(bytes);
  if (header) {
    fmt::print("| swatch | sides, tolerance | loops | triangles | .glb MB | script s | mesh s | write s | total s | "
               "loops/s | triangles/s | mesh / memcpy | peak MiB | relax s | relax iterations | mesh | triangles / loop |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  }
  fmt::print("| {}x{} | {}, {} | {:.0f} | {} | {:.1f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.0f} | {:.3g} | {:.1f} | {:.0f} | {} | {} | {} | {:.0f} |{}\n",
             wales, courses, density.sides, density.chord_tolerance, loops, triangles, static_cast<double>(bytes) / 1e6,
             script, mesh, write, total, loops / total, static_cast<double>(triangles) / total, mesh / copy, peak,
             relaxed ? fmt::format("{:.3f}", relax_seconds) : "off", relaxed ? std::to_string(relax_iterations) : "",
             instanced ? "instanced" : "flat", static_cast<double>(triangles) / loops,
             flatten_seconds >= 0.0 ? fmt::format(" flatten {:.3f} s, {:.1f} x a memcpy of its {:.0f} MB, {:.2f} x one into fresh memory",
                                                  flatten_seconds, flatten_seconds / memcpy_seconds(flatten_bytes),
                                                  static_cast<double>(flatten_bytes) / 1e6,
                                                  flatten_seconds / fresh_memcpy_seconds(flatten_bytes))
                                    : std::string());
  return 0;
}

}  // namespace knitc::cli
