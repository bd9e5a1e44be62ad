// The command line's words (commands.hpp).
#include "commands.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <string_view>
#include <system_error>

#include "knitout.hpp"
#include "writers/writers.hpp"

namespace knitc::cli {

namespace {

// A number that is one: CLI11's Range lets NaN through (every comparison with it is false).
const CLI::Validator finite(
    [](std::string& text) -> std::string {
      double v = 0.0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return "not a finite number: " + text;
      return "";
    },
    "FINITE");

}  // namespace

// "WxH" with both whole numbers from lo to hi, or nothing.
std::optional<std::pair<int, int>> dimensions(const std::string& text, int lo, int hi) {
  const auto x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  auto whole = [&](std::string_view part) -> std::optional<int> {
    long long v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (ec != std::errc() || end != part.data() + part.size() || part.empty() || v < lo || v > hi) return std::nullopt;
    return static_cast<int>(v);
  };
  const auto w = whole(std::string_view(text).substr(0, x));
  const auto h = whole(std::string_view(text).substr(x + 1));
  if (!w || !h) return std::nullopt;
  return std::pair{*w, *h};
}

namespace {

// What every command that runs a pattern takes.
void add_pattern_options(CLI::App* cmd, Args& a) {
  cmd->add_option("pattern", a.pattern, "the pattern script (.lua), a knitout machine program (.k, .knitout), or a printed pattern (any other file)")->required();
  cmd->add_option("-I,--include", a.run.module_dirs, "a folder `require` searches first (repeatable)");
  cmd->add_option("--seed", a.run.seed, "math.random's seed, over the pattern's own");
  cmd->add_option_function<std::uint64_t>(
         "--max-instructions", [&a](std::uint64_t millions) { a.run.limits.instructions = millions * 1'000'000; },
         "millions of Lua instructions a script may run (default 200)")
      ->check(CLI::Range(1, 100'000));
  cmd->add_option_function<std::size_t>(
         "--max-memory", [&a](std::size_t mib) { a.run.limits.memory_bytes = mib << 20; },
         "MiB of memory a script may hold (default 256)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--max-seconds", a.run.limits.seconds,
                  "seconds a script may run, whatever it calls (default 3, or 3 per 200 million --max-instructions)")
      ->check(finite)
      ->check(CLI::Range(0.01, 3600.0));
  cmd->add_flag("-q,--quiet", a.quiet, "print nothing on success");
  knitc::cli::add_printed_options(cmd, a.printed);
}

void add_compile_options(CLI::App* cmd, Args& a) {
  const std::map<std::string, knitc::yarn_paths::LoopModel> models{
      {"paper", knitc::yarn_paths::LoopModel::paper}, {"smooth", knitc::yarn_paths::LoopModel::smooth}};
  cmd->add_option("--loop-model", a.compile.loop_model,
                  "smooth: one C2 curve per course (default); paper: the seed paper's curve per loop")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case));
  const std::map<std::string, knitc::View> views{
      {"surface", knitc::View::surface}, {"wireframe", knitc::View::wireframe}, {"centreline", knitc::View::centreline}};
  cmd->add_option("--view", a.compile.view, "surface (default), wireframe or centreline")
      ->transform(CLI::CheckedTransformer(views, CLI::ignore_case));
  const std::map<std::string, bool> sections{{"tube", false}, {"fibres", true}};
  cmd->add_option("--section", a.compile.fibres,
                  "tube (default): each yarn a tube of its section; fibres: its plies' cores, fibres and flyaways, for "
                  "close-ups (docs/yarn.md, \"Fibres\")")
      ->transform(CLI::CheckedTransformer(sections, CLI::ignore_case));
  cmd->add_option("--textures", a.compile.textures,
                  "on (default, but for view, and for a fabric whose loops span under 16 px of a full view): bake each "
                  "yarn's plies and fibres into normal, occlusion and colour maps on its tube (docs/yarn.md, \"Baked "
                  "textures\"); off: plain tubes")
      ->transform(CLI::CheckedTransformer(std::map<std::string, bool>{{"on", true}, {"off", false}}, CLI::ignore_case));
  const std::map<std::string, knitc::nurbs::Parametrisation> params{
      {"chord", knitc::nurbs::Parametrisation::chord_length},
      {"centripetal", knitc::nurbs::Parametrisation::centripetal}};
  cmd->add_option("--parameters", a.compile.parametrisation, "data point parameters: chord (default) or centripetal")
      ->transform(CLI::CheckedTransformer(params, CLI::ignore_case));
  const std::map<std::string, knitc::Quality> qualities{
      {"draft", knitc::Quality::draft}, {"normal", knitc::Quality::normal}, {"fine", knitc::Quality::fine}};
  cmd->add_option("--quality", a.quality,
                  "mesh density: draft (6 sides, 5% chord error), normal (12, 1%: the default), fine (24, 0.25%)")
      ->transform(CLI::CheckedTransformer(qualities, CLI::ignore_case));
  cmd->add_option("--sides", a.compile.sides, "vertices around each tube ring, over --quality's")->check(CLI::Range(3, 256));
  cmd->add_option("--tolerance", a.compile.chord_tolerance,
                  "chord error of the tube surface as a fraction of the yarn diameter, over --quality's")
      ->check(finite)
      ->check(CLI::Range(1e-4, 1.0));
  const std::map<std::string, bool> on_off{{"on", true}, {"off", false}};
  cmd->add_option("--relax", a.compile.relax,
                  "on (the default for the smooth loop model): move the yarns apart until no two cores overlap, keeping "
                  "their lengths and crossings, and press their sections flat where they touch (docs/relaxation.md); off "
                  "(the paper model's default): the layout's curves as they are")
      ->transform(CLI::CheckedTransformer(on_off, CLI::ignore_case));
  const std::map<std::string, knitc::relax::Boundary> boundaries{{"free", knitc::relax::Boundary::free},
                                                                 {"held", knitc::relax::Boundary::held},
                                                                 {"periodic", knitc::relax::Boundary::periodic}};
  cmd->add_option("--edges", a.compile.relaxation.boundary,
                  "while relaxing: free (default), held (the cast-on and last course stay put) or periodic (the swatch is "
                  "one repeat of an endless fabric)")
      ->transform(CLI::CheckedTransformer(boundaries, CLI::ignore_case));
  auto* flatten = cmd->add_flag("--flatten", a.flatten,
                                "write every triangle, never an instanced repeat (for printing, simulation, or readers "
                                "without EXT_mesh_gpu_instancing)");
  cmd->add_flag("--instance", a.instance,
                "mesh a relaxed repeat once and place it across the fabric (EXT_mesh_gpu_instancing) whatever its size; by "
                "default only a fabric whose flat mesh would pass 1 million vertices is")
      ->excludes(flatten);
  cmd->add_flag("--stats", a.stats, "print counts, bounds and measures of the result");
  cmd->add_option("--threads", a.compile.threads, "threads to use (default: every core); the output is the same for any")
      ->check(CLI::Range(1, 256));
}


}  // namespace

void declare_commands(Commands& c) {
  CLI::App& app = c.app;
  app.set_version_flag("--version", "knitc " KNITC_VERSION);
  app.require_subcommand(1);

  c.build_cmd = app.add_subcommand("build", "compile a pattern script or a printed pattern into a glTF binary (.glb)");
  add_pattern_options(c.build_cmd, c.build);
  c.build_cmd->add_option("-o,--output", c.build.output, "the .glb to write (- for standard output)")->required();
  c.build_cmd->add_option("--centreline", c.build.centreline, "also write the centrelines and loop data points as JSON (mm)");
  auto* compress = c.build_cmd->add_flag("--compress", c.build.compress,
                                         "a smaller file: positions (uint16) and normals (int8) quantised with "
                                         "KHR_mesh_quantization, then every buffer view encoded by meshoptimizer "
                                         "(EXT_meshopt_compression); the default for an instanced fabric");
  c.build_cmd->add_flag("--no-compress", c.build.no_compress, "plain floats and indices, even for an instanced fabric")
      ->excludes(compress);
  add_compile_options(c.build_cmd, c.build);

  c.render_cmd = app.add_subcommand("render", "draw a lit preview of a pattern's fabric (.png)");
  add_pattern_options(c.render_cmd, c.render);
  c.render_cmd->add_option("-o,--output", c.render.output, "the .png to write (- for standard output)")->required();
  c.render_cmd->add_option("--size", c.render.size, "image size WxH of one view (default 960x720)");
  const std::map<std::string, knitc::render::RenderOptions::Side> sides{
      {"face", knitc::render::RenderOptions::Side::face},
      {"back", knitc::render::RenderOptions::Side::back},
      {"both", knitc::render::RenderOptions::Side::both}};
  c.render_cmd->add_option("--side", c.render.render.side, "face (default), back, or both side by side")
      ->transform(CLI::CheckedTransformer(sides, CLI::ignore_case));
  c.render_cmd->add_option("--light", c.render.light,
                           "photo (default): rays traced with Embree, soft shadows, occlusion, sheen, a perspective camera; "
                           "flat: the quick OpenGL preview, key and fill light")
      ->check(CLI::IsMember({"photo", "flat"}));
  c.render_cmd->add_option("--samples", c.render.trace.samples, "photo: samples a pixel (default 16)")->check(CLI::Range(1, 1024));
  c.render_cmd->add_option("--sample-seed", c.render.trace.seed, "photo: the seed of the samples' jitter (default 1)");
  c.render_cmd->add_option("--close-up", c.render.close_up, "photo: a close-up this many loops across at the fabric's middle")
      ->check(CLI::Range(1.0, 1000.0));
  add_compile_options(c.render_cmd, c.render);

  c.snapshot_cmd = app.add_subcommand("snapshot", "print a stable summary of the compiled mesh, for snapshot tests");
  add_pattern_options(c.snapshot_cmd, c.snapshot);
  c.snapshot_cmd->add_option("-o,--output", c.snapshot.output, "write it to this file instead of standard output");
  add_compile_options(c.snapshot_cmd, c.snapshot);

  c.chart_cmd = app.add_subcommand("chart", "print the pattern's stitch chart as text");
  add_pattern_options(c.chart_cmd, c.chart);

  c.check_cmd = app.add_subcommand("check", "validate a pattern only (fast; for editors and hooks)");
  add_pattern_options(c.check_cmd, c.check);

  c.knitout_cmd = app.add_subcommand("knitout", "write the pattern as a knitout program for a V-bed knitting machine (.k; docs/knitout.md)");
  add_pattern_options(c.knitout_cmd, c.knitout);
  c.knitout_cmd->add_option("-o,--output", c.knitout.output, "the .k to write (- for standard output)")->required();
  c.knitout_cmd->add_option("--machine", c.knitout_machine, "the machine profile: swg (a Shima SWG-like, 15 gauge; default) or kniterate (7 gauge)")
      ->check(CLI::IsMember({"swg", "kniterate"}));

  c.bench_cmd = app.add_subcommand("bench", "time the whole job on a jersey swatch of WxH loops (one table row)");
  c.bench_cmd->add_option("--swatch", c.bench_size, "wales x courses, e.g. 150x250 (default)");
  c.bench_cmd->add_flag("--header", c.bench_header, "print the table's header first");
  c.bench_cmd->add_flag("--flat", c.bench_flat,
                        "jersey knitted flat and bound off, a garment piece (relaxed by repeat, instanced when large), "
                        "rather than in the round");
  add_compile_options(c.bench_cmd, c.bench);

  c.reference_cmd = app.add_subcommand("reference", "print the pattern language reference (docs/language.md)");

  c.view_cmd = app.add_subcommand("view",
                                  "serve the fabric to a browser on 127.0.0.1 and rebuild it whenever the pattern or a module "
                                  "it requires changes (Ctrl-C stops; docs/view.md)");
  add_pattern_options(c.view_cmd, c.view);
  c.view_cmd->add_option("--port", c.view_port, "the port on 127.0.0.1 (default 0: a free one)")->check(CLI::Range(0, 65535));
  c.view_cmd->add_flag("--no-open", c.view_no_open, "print the address only; do not open a browser");
  add_compile_options(c.view_cmd, c.view);

  c.gallery_cmd = app.add_subcommand("gallery", "write a pattern library as a static site: an index, and a page per pattern "
                                                "with its 3D view, chart, figures and source (docs/view.md)");
  c.gallery_cmd->add_option("folder", c.gallery.pattern, "the library: every *.lua directly in it")->required();
  c.gallery_cmd->add_option("-o,--output", c.gallery.output, "the folder to write the site to")->required();
  c.gallery_cmd->add_option("-I,--include", c.gallery.run.module_dirs, "a folder `require` searches first (repeatable)");
  c.gallery_cmd->add_flag("-q,--quiet", c.gallery.quiet, "print nothing on success");
  add_compile_options(c.gallery_cmd, c.gallery);
}

// Outputs that would clobber the pattern or each other, or binary to a terminal: the
// exit code, or 0. Paths are compared as the files they name (DIR/../X.glb is X.glb, a
// link is its target).
int refuse_bad_outputs(const Commands& c) {
  for (const Args* args : {&c.build, &c.render, &c.snapshot, &c.knitout}) {
    if (args->pattern.empty()) continue;
    const std::string pattern_file = knitc::writers::file_identity(args->pattern);
    std::vector<std::pair<std::string, std::string>> seen;  // identity, path
    for (const std::string* output : {&args->output, &args->centreline}) {
      if (output->empty()) continue;
      const std::string id = knitc::writers::file_identity(*output);
      if (id == pattern_file) {
        report("knitc: " + *output + " would overwrite the pattern itself");
        return exit_usage;
      }
      for (const auto& [other_id, other] : seen) {
        if (id == other_id) {
          report("knitc: " + *output + " and " + other + " are the same file; give each output its own");
          return exit_usage;
        }
      }
      seen.emplace_back(id, *output);
    }
  }
  // build writes a glTF binary whatever the name: a name that says another format would
  // get a file no reader of that format opens.
  if (!c.build.output.empty() && c.build.output != "-") {
    std::string ext = std::filesystem::path(c.build.output).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    const std::pair<const char*, const char*> others[] = {
        {".json", "the centrelines as JSON are --centreline FILE.json"},
        {".gltf", "name it .glb: knitc writes the binary form, which glTF readers open"},
        {".png", "pictures are knitc render PATTERN -o FILE.png"},
        {".k", "machine programs are knitc knitout PATTERN -o FILE.k"},
        {".knitout", "machine programs are knitc knitout PATTERN -o FILE.k"},
        {".lua", "that names a pattern script"}};
    for (const auto& [other, hint] : others)
      if (ext == other) {
        report("knitc: build writes a glTF binary (.glb), not " + ext + ": " + hint);
        return exit_usage;
      }
  }
  for (const Args* args : {&c.build, &c.render}) {
    if (args->output == "-" && ::isatty(STDOUT_FILENO) != 0) {
      report("knitc: -o - would write binary data to the terminal; redirect it (> file, | program) or name a file");
      return exit_usage;
    }
  }
  return 0;
}

// The defaults that follow other options: a larger instruction budget brings a longer
// deadline unless one is given; the loop model says whether to relax unless --relax
// does; --quality sets the density, --sides and --tolerance win.
void settle_defaults(Commands& c) {
  for (auto [cmd, args] : {std::pair{c.build_cmd, &c.build}, std::pair{c.render_cmd, &c.render},
                           std::pair{c.snapshot_cmd, &c.snapshot}, std::pair{c.chart_cmd, &c.chart},
                           std::pair{c.check_cmd, &c.check}, std::pair{c.view_cmd, &c.view}, std::pair{c.knitout_cmd, &c.knitout}}) {
    if (!cmd->parsed() || cmd->get_option("--max-seconds")->count() != 0) continue;
    const knitc::runtime::Limits defaults;
    args->run.limits.seconds = defaults.seconds * std::max(1.0, static_cast<double>(args->run.limits.instructions) /
                                                                    static_cast<double>(defaults.instructions));
  }
  for (auto [cmd, args] : {std::pair{c.build_cmd, &c.build}, std::pair{c.render_cmd, &c.render},
                           std::pair{c.snapshot_cmd, &c.snapshot}, std::pair{c.view_cmd, &c.view},
                           std::pair{c.gallery_cmd, &c.gallery}}) {
    if (cmd->parsed() && cmd->get_option("--relax")->count() == 0)
      args->compile.relax = knitc::relaxed_by_default(args->compile.loop_model);
  }
  // The live view redraws on every edit and every turn of the camera: bare tubes unless
  // asked, since under software GL (no GPU) the maps cost a few tenths of a second a frame.
  if (c.view_cmd->parsed() && c.view_cmd->get_option("--textures")->count() == 0) c.view.compile.textures = false;
  for (auto [cmd, args] : {std::pair{c.build_cmd, &c.build}, std::pair{c.render_cmd, &c.render},
                           std::pair{c.snapshot_cmd, &c.snapshot}, std::pair{c.bench_cmd, &c.bench},
                           std::pair{c.view_cmd, &c.view}, std::pair{c.gallery_cmd, &c.gallery}}) {
    if (!cmd->parsed()) continue;
    args->compile.instancing = args->flatten    ? knitc::Instancing::flatten
                               : args->instance ? knitc::Instancing::instance
                                                : knitc::Instancing::automatic;
    const bool given = cmd->get_option("--sides")->count() != 0 || cmd->get_option("--tolerance")->count() != 0;
    args->compile.density_from_view = !args->quality && !given;
    const CLI::Option* textures = cmd->get_option_no_throw("--textures");
    args->compile.textures_from_view = textures == nullptr || textures->count() == 0;
    if (!args->quality) continue;
    const knitc::Density d = knitc::density(*args->quality);
    if (cmd->get_option("--sides")->count() == 0) args->compile.sides = d.sides;
    if (cmd->get_option("--tolerance")->count() == 0) args->compile.chord_tolerance = d.chord_tolerance;
  }
}

}  // namespace knitc::cli
