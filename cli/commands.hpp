// The command line's words: every subcommand, the options it takes and the arguments
// they fill (declared with CLI11), the defaults that follow from other options, and the
// outputs refused before anything runs. knitc.cpp runs what they say.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "compile.hpp"
#include "printed.hpp"
#include "render.hpp"
#include "runtime.hpp"
#include "trace.hpp"

namespace knitc::cli {

// Exit codes (knitc.cpp's header says when each is given).
inline constexpr int exit_pattern = 1;
inline constexpr int exit_usage = 2;
inline constexpr int exit_io = 3;
inline constexpr int exit_internal = 4;

// Everything knitc prints about a problem goes through here: a message may quote a
// script's text or a path, which must not reach the terminal raw.
inline void report(const std::string& message) { fmt::print(stderr, "{}\n", knitc::runtime::printable(message, 4000)); }

// What one subcommand was told.
struct Args {
  std::string pattern;
  std::string output;
  std::string centreline;
  knitc::runtime::RunOptions run;
  knitc::cli::PrintedArgs printed;  // a printed pattern's declaration
  knitc::CompileOptions compile = [] {
    knitc::CompileOptions o;
    o.textures = true;  // the programs bake the yarn's maps unless --textures off
    return o;
  }();
  knitc::render::RenderOptions render;
  knitc::render::TraceOptions trace;
  std::string light = "photo";
  double close_up = 0.0;  // loops across; 0: the whole fabric
  std::string size = "960x720";
  std::optional<knitc::Quality> quality;
  bool stats = false;
  bool quiet = false;
  bool compress = false, no_compress = false;
  bool flatten = false, instance = false;
};

// Every subcommand and the arguments it fills.
struct Commands {
  CLI::App app{"knitc: compiles knitting pattern scripts into yarn-level 3D fabric", "knitc"};
  Args build, render, snapshot, chart, check, bench, view, gallery, knitout;
  std::string knitout_machine = "swg";
  int view_port = 0;
  bool view_no_open = false;
  std::string bench_size = "150x250";
  bool bench_header = false, bench_flat = false;
  CLI::App *build_cmd = nullptr, *render_cmd = nullptr, *snapshot_cmd = nullptr, *chart_cmd = nullptr,
           *check_cmd = nullptr, *bench_cmd = nullptr, *reference_cmd = nullptr, *view_cmd = nullptr,
           *gallery_cmd = nullptr, *knitout_cmd = nullptr;
};

// Declares every subcommand and its options on c.app.
void declare_commands(Commands& c);

// Outputs that would clobber the pattern or each other, or binary to a terminal: the
// exit code, or 0.
int refuse_bad_outputs(const Commands& c);

// The defaults that follow other options, once c.app has parsed.
void settle_defaults(Commands& c);

// "WxH" with both whole numbers from lo to hi, or nothing.
std::optional<std::pair<int, int>> dimensions(const std::string& text, int lo, int hi);

}  // namespace knitc::cli
