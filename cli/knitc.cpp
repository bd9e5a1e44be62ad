// knitc: the command line. The only place that wires runtime, compiler and writers.
// Exit codes: 0 success, 1 a problem in the pattern (file:line: ...), 2 bad command-line
// use, 3 a file that could not be read or written (disk full, permissions, not a
// regular file), 4 out of memory or a fault of knitc's own.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>

#include <unistd.h>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench.hpp"
#include "knitout.hpp"
#include "printed.hpp"
#include "sources.hpp"
#include "stats.hpp"
#include "view.hpp"
#include "gallery.hpp"
#include "compile.hpp"
#include "measure/measure.hpp"
#include "render.hpp"
#include "trace.hpp"
#include "runtime.hpp"
#include "language/chart.hpp"
#include "writers/writers.hpp"

#include "commands.hpp"

using knitc::cli::Args;
using knitc::cli::Commands;
using knitc::cli::dimensions;
using knitc::cli::exit_internal;
using knitc::cli::exit_io;
using knitc::cli::exit_pattern;
using knitc::cli::exit_usage;
using knitc::cli::report;

namespace {

// --compress where it pays: on for an instanced fabric (a garment's file, for readers that
// know the extensions anyway), off for a flat one (every reader opens it), unless told.
bool compressed(const Args& args, const knitc::Fabric& fabric) {
  if (args.compress || args.no_compress) return args.compress;
  return fabric.instanced;
}

// The pattern, or the exit code when it could not be had. Warnings go to stderr.
std::variant<knitc::Pattern, int> load(const Args& args) {
  try {
    auto result = knitc::cli::read_pattern(args.pattern, args.printed.options, args.run);
    for (const auto& w : result.warnings) report(w);
    return std::move(result.pattern);
  } catch (const knitc::runtime::PatternError& e) {
    for (const auto& w : e.warnings) report(w);
    report(e.what());
    return exit_pattern;
  } catch (const knitc::runtime::FileError& e) {
    report(std::string("knitc: ") + e.what());
    return exit_io;
  }
}

// Progress on a terminal: the stage and its percentage on stderr, once a build has taken
// more than a second; nothing when stderr is not a terminal or with --quiet.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled && ::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  ~Progress() {
    if (shown_) std::fputs("\r\033[K", stderr);
  }
  void operator()(const char* stage, double fraction) {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_ && stage == last_stage_) return;
    if (std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
    last_ = percent;
    last_stage_ = stage;
    shown_ = true;
    std::fprintf(stderr, "\rknitc: %s %3d%%\033[K", stage, percent);
  }

 private:
  bool enabled_;
  bool shown_ = false;
  int last_ = -1;
  const char* last_stage_ = nullptr;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
};

// The relaxation's wall time, told by the stage's progress: times are the caller's.
struct RelaxClock {
  std::chrono::steady_clock::time_point start;
  double seconds = 0.0;
  void operator()(const char* stage, double fraction) {
    if (std::string_view(stage) != "relax") return;
    if (fraction == 0.0) start = std::chrono::steady_clock::now();
    else seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
};

std::variant<knitc::Fabric, int> compile(const knitc::Pattern& pattern, const Args& args, RelaxClock& clock) {
  try {
    Progress progress(!args.quiet);
    knitc::CompileOptions options = args.compile;
    options.progress = [&](const char* stage, double fraction) {
      progress(stage, fraction);
      clock(stage, fraction);
    };
    return knitc::compile(pattern, options);
  } catch (const knitc::CompileError& e) {
    report(e.what());
    return exit_pattern;
  }
}

int write(const std::vector<knitc::writers::OutputFile>& files) {
  try {
    knitc::writers::write_files(files);
    return 0;
  } catch (const knitc::writers::OutputError& e) {
    report(std::string("knitc: ") + e.what());
    return exit_io;
  }
}

struct Compiled {
  knitc::Pattern pattern;
  knitc::Fabric fabric;
  double relax_seconds = 0.0;  // wall time of the relaxation, for --stats only
};

// The pattern run and compiled, or the exit code when either failed.
std::variant<Compiled, int> load_and_compile(const Args& args) {
  auto loaded = load(args);
  if (const int* code = std::get_if<int>(&loaded)) return *code;
  RelaxClock clock;
  auto compiled = compile(std::get<knitc::Pattern>(loaded), args, clock);
  if (const int* code = std::get_if<int>(&compiled)) return *code;
  if (const auto& f = std::get<knitc::Fabric>(compiled); f.crossings_checked)
    if (const std::size_t through = knitc::measure::passed_through(f.crossings); through > 0)
      report(fmt::format("knitc: warning: relaxing passed a yarn through another at {} of {} crossings (see docs/relaxation.md, "
                         "\"The library's gauges\"); --relax off draws the layout as it is",
                         through, f.crossings.kept + f.crossings.flipped + f.crossings.lost));
  // A relaxation that stopped at its sweep limit with cores still into each other past its
  // own tolerance has not found a fabric that could exist (a full-needle rib widening from
  // a jersey: docs/knitout.md, "What is approximated"); said, not hidden behind the file.
  if (const auto& f = std::get<knitc::Fabric>(compiled); knitc::cores_left_overlapping(f, args.compile.relaxation))
    report(fmt::format("knitc: warning: the relaxation stopped after {} sweeps with yarn cores still {:.2f} core diameters into each "
                       "other (the layout's: {:.2f}); this 3D fabric is not settled; --relax off draws the layout as it is",
                       f.relaxation.iterations, f.relaxation.end_overlap, f.relaxation.start_overlap));
  return Compiled{std::move(std::get<knitc::Pattern>(loaded)), std::move(std::get<knitc::Fabric>(compiled)), clock.seconds};
}

int build(const Args& args) {
  auto result = load_and_compile(args);
  if (const int* code = std::get_if<int>(&result)) return *code;
  const auto& [pattern, fabric, relax_seconds] = std::get<Compiled>(result);
  std::vector<knitc::writers::OutputFile> files;
  files.push_back({args.output, [&](std::ostream& out) {
                     const bool small = compressed(args, fabric);
                     knitc::writers::write_glb(fabric.mesh, "knitc " KNITC_VERSION, out, {small, small, args.compile.threads});
                   }});
  if (!args.centreline.empty())
    files.push_back(knitc::writers::text_file(args.centreline, knitc::writers::centreline_json(pattern, fabric, args.compile.loop_model)));
  if (const int code = write(files); code != 0) return code;
  if (args.stats) print_stats(pattern, fabric, relax_seconds);
  if (!args.quiet && !args.stats && args.output != "-")
    report(fmt::format("knitc: wrote {} ({} loops)", args.output, fabric.layout.loops.size()));
  return 0;
}

int render(const Args& args) {
  auto result = load_and_compile(args);
  if (const int* code = std::get_if<int>(&result)) return *code;
  const auto& [pattern, fabric, relax_seconds] = std::get<Compiled>(result);
  std::string png;
  try {
    // Traced where there are surfaces to light; lines (wireframes, centrelines) rasterised.
    if (args.light == "photo" && args.compile.view == knitc::View::surface) {
      knitc::render::TraceOptions trace = args.trace;
      trace.width = args.render.width;
      trace.height = args.render.height;
      trace.side = args.render.side;
      trace.background = args.render.background;
      trace.threads = args.compile.threads;
      trace.close_up = args.close_up * fabric.layout.loop_width;
      png = knitc::render::traced_png(fabric.mesh, trace);
    } else {
      png = knitc::render::png(fabric.mesh, args.render);
    }
  } catch (const std::exception& e) {
    report(std::string("knitc: cannot render: ") + e.what());
    return exit_internal;
  }
  if (const int code = write({knitc::writers::text_file(args.output, std::move(png))}); code != 0) return code;
  if (args.stats) print_stats(pattern, fabric, relax_seconds);
  if (!args.quiet && !args.stats && args.output != "-") report("knitc: wrote " + args.output);
  return 0;
}

int snapshot(const Args& args) {
  auto result = load_and_compile(args);
  if (const int* code = std::get_if<int>(&result)) return *code;
  const auto& [pattern, fabric, relax_seconds] = std::get<Compiled>(result);
  const std::string text = knitc::writers::snapshot(pattern, fabric, knitc::measure::measure(pattern, fabric.layout, fabric.pieces));
  return write({knitc::writers::text_file(args.output.empty() ? "-" : args.output, text)});
}

int chart(const Args& args) {
  auto loaded = load(args);
  if (const int* code = std::get_if<int>(&loaded)) return *code;
  return write({knitc::writers::text_file("-", knitc::language::chart_text(std::get<knitc::Pattern>(loaded)))});
}

// knitc knitout: the pattern as a machine program, checked by reading it back.
int knitout_out(const Args& args, const std::string& machine) {
  auto loaded = load(args);
  if (const int* code = std::get_if<int>(&loaded)) return *code;
  const auto& pattern = std::get<knitc::Pattern>(loaded);
  const knitc::knitout::Profile profile = knitc::knitout::profile_named(machine);
  knitc::knitout::Exported exported;
  try {
    exported = knitc::knitout::export_pattern(pattern, profile);
  } catch (const knitc::knitout::KnitoutError& e) {
    report(e.what());
    return exit_pattern;
  }
  for (const auto& w : exported.warnings) report(w);
  if (const auto problems = knitc::knitout::check_program(exported.text, args.output, profile); !problems.empty()) {
    for (const auto& p : problems) report("knitc: the program written fails its own check: " + p);
    return exit_internal;
  }
  if (const int code = write({knitc::writers::text_file(args.output, exported.text)}); code != 0) return code;
  if (!args.quiet && args.output != "-") report("knitc: wrote " + args.output + " for the " + profile.name);
  return 0;
}

int check(const Args& args) {
  auto loaded = load(args);
  if (const int* code = std::get_if<int>(&loaded)) return *code;
  const auto& p = std::get<knitc::Pattern>(loaded);
  try {
    // What only the knit graph sees: a dropped wale that cannot unravel. Built only then,
    // and not past the size the compiler would refuse anyway: check stays fast.
    const bool drops = std::any_of(p.courses.begin(), p.courses.end(), [](const knitc::Course& c) {
      return std::any_of(c.ops.begin(), c.ops.end(),
                         [](const knitc::Op& op) { return knitc::stitch(op.stitch).family == knitc::StitchFamily::drop; });
    });
    if (drops && knitc::loops_of(p) <= static_cast<long long>(knitc::max_loops)) knitc::knit(p);
  } catch (const knitc::CompileError& e) {
    report(e.what());
    return exit_pattern;
  }
  if (!args.quiet) {
    fmt::print(stderr, "{}: {} rows, {} stitches cast on, {} live at the end{}\n", args.pattern, p.courses.size(),
               p.cast_on, p.courses.empty() ? p.cast_on : knitc::produced(p.courses.back()), p.bound_off ? " (bound off)" : "");
  }
  return 0;
}

}  // namespace

int run(int argc, char** argv);

// Never a crash: whatever escapes is reported, and no output has been renamed into place.
int main(int argc, char** argv) {
  knitc::writers::remove_temporaries_on_signals();
  int code = exit_internal;
  try {
    code = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("knitc: out of memory; knit a smaller piece or use --quality draft\n", stderr);
    return exit_internal;
  } catch (const std::system_error& e) {  // fmt::print to a full disk or a closed pipe
    report(std::string("knitc: cannot write standard output: ") + e.code().message());
    return exit_io;
  } catch (const std::exception& e) {
    report(std::string("knitc: internal error: ") + e.what());
    return exit_internal;
  }
  // What went to standard output must have got there (a full disk, a closed pipe).
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    report(std::string("knitc: cannot write standard output: ") + std::strerror(errno));
    return code == 0 ? exit_io : code;
  }
  return code;
}

namespace {

int run_bench(const Commands& c) {
  const auto size = dimensions(c.bench_size, 1, 100000);
  if (!size) {
    report("knitc: --swatch is \"" + c.bench_size + "\"; give WALESxCOURSES with each from 1 to 100000, e.g. 150x250");
    return exit_usage;
  }
  try {
    return knitc::cli::bench(size->first, size->second, c.bench.compile, c.bench_header, c.bench_flat);
  } catch (const knitc::CompileError& e) {
    report(e.what());
    return exit_pattern;
  } catch (const knitc::writers::OutputError& e) {
    report(std::string("knitc: ") + e.what());
    return exit_io;
  }
}

int dispatch(Commands& c) {
  if (c.build_cmd->parsed()) return build(c.build);
  if (c.render_cmd->parsed()) {
    const auto size = dimensions(c.render.size, 16, 8192);
    if (!size) {
      report("knitc: --size is \"" + c.render.size + "\"; give WxH with each from 16 to 8192, e.g. 960x720");
      return exit_usage;
    }
    c.render.render.width = size->first;
    c.render.render.height = size->second;
    // A close-up is meshed for the loops it shows, not for the whole fabric's view.
    if (c.render.close_up > 0.0) c.render.compile.close_up_loop_pixels = size->first / c.render.close_up;
    return render(c.render);
  }
  if (c.snapshot_cmd->parsed()) return snapshot(c.snapshot);
  if (c.bench_cmd->parsed()) return run_bench(c);
  if (c.chart_cmd->parsed()) return chart(c.chart);
  if (c.check_cmd->parsed()) return check(c.check);
  if (c.knitout_cmd->parsed()) return knitout_out(c.knitout, c.knitout_machine);
  if (c.reference_cmd->parsed()) return write({knitc::writers::text_file("-", knitc::runtime::language_reference())});
  if (c.view_cmd->parsed()) {
    knitc::cli::ViewOptions v;
    v.pattern = c.view.pattern;
    v.run = c.view.run;
    v.printed = c.view.printed.options;
    v.compile = c.view.compile;
    v.port = c.view_port;
    v.open = !c.view_no_open;
    v.quiet = c.view.quiet;
    return knitc::cli::view(v);
  }
  if (c.gallery_cmd->parsed()) {
    knitc::cli::GalleryOptions g;
    g.dir = c.gallery.pattern;
    g.site = c.gallery.output;
    g.run = c.gallery.run;
    g.compile = c.gallery.compile;
    g.quiet = c.gallery.quiet;
    return knitc::cli::gallery(g);
  }
  return exit_usage;
}

}  // namespace

int run(int argc, char** argv) {
  Commands c;
  declare_commands(c);
  try {
    c.app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return c.app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return c.app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return c.app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 would print the bad argument as it came; it goes through report() like
    // every other message (an argument can hold terminal escapes too).
    report(e.what());
    report("Run with --help for more information.");
    return exit_usage;
  }
  if (const int code = refuse_bad_outputs(c); code != 0) return code;
  for (auto [cmd, args] : {std::pair{c.build_cmd, &c.build}, std::pair{c.render_cmd, &c.render},
                           std::pair{c.snapshot_cmd, &c.snapshot}, std::pair{c.chart_cmd, &c.chart},
                           std::pair{c.check_cmd, &c.check}, std::pair{c.view_cmd, &c.view}, std::pair{c.knitout_cmd, &c.knitout}}) {
    if (!cmd->parsed()) continue;
    if (const auto problem = knitc::cli::settle_printed_options(cmd, args->pattern, args->printed)) {
      report(*problem);
      return exit_usage;
    }
  }
  settle_defaults(c);
  return dispatch(c);
}
