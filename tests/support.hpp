// Helpers shared by the tests: running the knitc binary, scratch directories, and a
// few patterns compiled in memory.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "compile.hpp"
#include "runtime.hpp"

namespace knitc::test {

// A course's stitches by name, in face view, left to right.
inline std::vector<std::string> names(const Course& c) {
  std::vector<std::string> out;
  for (const Op& op : c.ops) out.emplace_back(stitch(op.stitch).name);
  return out;
}

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// A script using the pattern library: line 1 declares the pattern, line 2 requires the
// library (ribs, cables, lace), line 3 casts on, the body starts on line 4.
inline std::string library_script(const std::string& knitting, int stitches, const std::string& body) {
  return "pattern { name = \"m\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.0 } }, "
         "knitting = \"" + knitting + "\" }\n"
         "local ribs, cables, lace = require \"ribs\", require \"cables\", require \"lace\"\n"
         "cast_on(" + std::to_string(stitches) + ")\n" + body;
}

inline Pattern run_with_library(const std::string& knitting, int stitches, const std::string& body) {
  return runtime::run_pattern(library_script(knitting, stitches, body), "t.lua").pattern;
}

// The message a pattern script fails with, or "" if it runs.
inline std::string script_error(const std::string& source, const std::string& file = "t.lua",
                                const runtime::RunOptions& options = {}) {
  try {
    runtime::run_pattern(source, file, options);
  } catch (const runtime::PatternError& e) {
    return e.what();
  }
  return "";
}

// A fresh, empty directory for one test, under the build tree.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("knitc-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The folder beside the repository that holds the corpus and the seed paper's data
// (../shared). A test that needs it skips where it is missing, but fails under CI
// (.ci/run sets KNITC_REQUIRE_SHARED), where it must be there.
inline std::filesystem::path shared_dir() { return std::filesystem::path(KNITC_SOURCE_DIR) / ".." / "shared"; }
#define KNITC_NEED_SHARED(path)                                                                  \
  do {                                                                                           \
    if (!std::filesystem::exists(path)) {                                                        \
      if (std::getenv("KNITC_REQUIRE_SHARED") != nullptr) FAIL() << "missing under CI: " << (path); \
      GTEST_SKIP() << "no " << (path) << " beside the repository";                              \
    }                                                                                            \
  } while (0)

// The directory whose .glb files the validator test checks after the unit tests.
inline std::filesystem::path glb_dir() {
  std::filesystem::create_directories(KNITC_GLB_DIR);
  return KNITC_GLB_DIR;
}

// Runs `knitc ARGS` (arguments already shell-quoted where needed), from the source tree.
inline CommandResult run_knitc(const std::string& args) {
  const auto dir = scratch_dir("run");
  const std::string cmd = std::string("cd '") + KNITC_SOURCE_DIR + "' && '" + KNITC_BINARY + "' " + args +
                          " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(dir / "out");
  r.err = read_text(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

// Stockinette knitted flat: knit right-side rows, purl wrong-side rows; no bind-off.
inline std::string jersey_source(int stitches, int rows, double w = 4.0, double h = 4.2, double t = 2.0,
                                 double d = 1.0) {
  std::ostringstream s;
  s << "pattern {\n  name = \"jersey\",\n  gauge = { loop_width = " << w << ", loop_height = " << h
    << ", thickness = " << t << " },\n  yarns = { A = { diameter = " << d << ", color = \"#d9c8a9\" } },\n"
    << "  knitting = \"flat\",\n}\n"
    << "cast_on(" << stitches << ")\nfor i = 1, " << rows << " do row(i % 2 == 1 and \"k\" or \"p\") end\n";
  return s.str();
}

inline Pattern jersey(int stitches, int rows, double w = 4.0, double h = 4.2, double t = 2.0, double d = 1.0) {
  return runtime::run_pattern(jersey_source(stitches, rows, w, h, t, d), "jersey.lua").pattern;
}

// The yarns' centrelines only (no tube mesh), at a coarse chord tolerance: what the
// relaxation tests measure. Relaxed or not.
inline CompileOptions centrelines(bool relax) {
  CompileOptions o;
  o.view = View::centreline;
  o.chord_tolerance = 0.05;
  o.relax = relax;
  return o;
}

}  // namespace knitc::test
