#include "compile.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "parallel.hpp"
#include "fibres/bake.hpp"
#include "fibres/fibres.hpp"
#include "tiles/tiles.hpp"
#include "relax/press.hpp"

namespace knitc {

Density density(Quality quality) {
  switch (quality) {
    case Quality::draft: return {6, 0.05};
    case Quality::normal: return {12, 0.01};
    case Quality::fine: return {24, 0.0025};
  }
  return {12, 0.01};
}

ViewDensity density_for_view(const layout::Layout& layout, int width, int height) {
  const double across = std::max(static_cast<double>(layout.wales), 1.0) * layout.loop_width;
  const double up = std::max(layout::laid_height(layout), layout.loop_width);
  return density_for_loop_pixels(std::min(width / across, height / up) * layout.loop_width);
}

ViewDensity density_for_loop_pixels(double loop) {
  if (loop >= 40.0) return {density(Quality::normal), loop};
  if (loop >= 16.0) return {{8, 0.025}, loop};
  // A loop a few pixels across: a chord error of about half a pixel (a loop's width over
  // 8 on the yarn's diameter, 2 / pixels of it), never finer than draft, at most a half;
  // round the ring, the fewest sides whose chord error (the sagitta of a side, (1 - cos
  // pi/n) / 2 of the diameter) is within it.
  const double tolerance = std::clamp(2.0 / loop, 0.05, coarsest_view_density.chord_tolerance);
  int sides = coarsest_view_density.sides;
  while ((1.0 - std::cos(std::numbers::pi / sides)) / 2.0 > tolerance) ++sides;
  return {{sides, tolerance}, loop, false};
}

namespace {

std::string millions(double n) {
  char text[32];
  if (n < 1e5) std::snprintf(text, sizeof text, "%.0f", n);
  else std::snprintf(text, sizeof text, "%.1f million", n / 1e6);
  return text;
}

// "file:line: " of the course at which the fabric passes `share` of its loops: where a
// fabric too large to make grows past the limit, the line a designer would shorten.
std::string where_it_passes(const Pattern& pattern, double share) {
  if (pattern.courses.empty()) return pattern.name + ":1: ";
  double total = static_cast<double>(pattern.cast_on);
  for (const Course& c : pattern.courses) total += static_cast<double>(c.ops.size());
  double so_far = static_cast<double>(pattern.cast_on);
  const Course* at = &pattern.courses.back();
  for (const Course& c : pattern.courses) {
    so_far += static_cast<double>(c.ops.size());
    if (so_far >= share * total) {
      at = &c;
      break;
    }
  }
  return at->where.file + ":" + std::to_string(std::max(at->where.line, 1)) + ": ";
}

[[noreturn]] void too_many_vertices(const Pattern& pattern, double vertices, const char* about) {
  throw CompileError(where_it_passes(pattern, static_cast<double>(max_vertices) / vertices) + "the mesh would have " + about +
                     std::to_string(static_cast<long long>(vertices / 1e6)) + " million vertices, over knitc's limit of " +
                     std::to_string(max_vertices / 1'000'000) + " million vertices; knit a smaller piece, or use --quality draft");
}

curves::Options curve_options(const CompileOptions& options) {
  return {options.parametrisation, curves::frame_kind(options.loop_model), options.chord_tolerance, options.threads};
}

// A yarn dyed along its length colours no two tiles alike.
bool dyed(const Pattern& pattern) {
  return std::any_of(pattern.yarns.begin(), pattern.yarns.end(), [](const Yarn& y) { return !y.colours.empty(); });
}

// A flat fabric relaxed by its repeat may be instanced: then its plain mesh's size, known
// only once the repeat is tiled, is no reason to refuse it early.
bool may_tile(const CompileOptions& options, const Pattern& pattern, Knitting knitting) {
  return options.relax && options.view == View::surface && knitting == Knitting::flat &&
         options.instancing != Instancing::flatten && !dyed(pattern) && !options.fibres;
}

void report(const CompileOptions& options, const char* stage, double fraction) {
  if (options.progress) options.progress(stage, fraction);
}

}  // namespace

double least_vertices(const Pattern& pattern, const CompileOptions& options) {
  // Half the rings the plain loop needs, about 55 at 1% tolerance, scaling as
  // tolerance^-1/2. The density from the view is known only once laid out: the coarsest
  // it can be, till then.
  const Density least = options.density_from_view ? coarsest_view_density : Density{options.sides, options.chord_tolerance};
  double per_ring = 1e30;
  for (const Yarn& y : pattern.yarns) per_ring = std::min(per_ring, static_cast<double>(tubes::vertex_count(y, 1000, least.sides)) / 1000.0);
  const double rings_per_loop = 0.5 * 55.0 * std::sqrt(0.01 / least.chord_tolerance);
  return static_cast<double>(loops_of(pattern)) * rings_per_loop * per_ring;
}

Fabric compile(const Pattern& pattern, const CompileOptions& options) {
  assert(options.sides >= 3 && options.chord_tolerance > 0.0);
  const auto loops = static_cast<std::uint64_t>(loops_of(pattern));
  if (loops > max_loops)
    throw CompileError(where_it_passes(pattern, static_cast<double>(max_loops) / static_cast<double>(loops)) + "the fabric has " +
                       std::to_string(loops) + " loops; knitc lays out at most " + std::to_string(max_loops) +
                       " (knitc check and chart take more)");
  // A cautious lower bound before the layout turns away the hopeless in a moment.
  const double least = least_vertices(pattern, options);
  if (least > static_cast<double>(max_vertices) && !may_tile(options, pattern, pattern.knitting))
    too_many_vertices(pattern, least, "at least ");
  layout::Layout layout;
  try {
    layout = layout::lay_out(pattern, knit(pattern));
  } catch (const std::invalid_argument& e) {
    throw CompileError(where_it_passes(pattern, 1.0) + e.what());
  }
  return compile(pattern, std::move(layout), options);
}

knit_graph::Graph knit(const Pattern& pattern) {
  try {
    return knit_graph::build(pattern);
  } catch (const knit_graph::RowError& e) {
    // The runtime checks counts as the script runs; what the graph alone sees (a wale
    // that cannot unravel) is reported at the row that asks for it.
    const auto at = static_cast<std::size_t>(e.course);
    if (at < 1 || at > pattern.courses.size()) throw CompileError(where_it_passes(pattern, 1.0) + e.what());
    const SourceLocation& where = pattern.courses[at - 1].where;
    throw CompileError(where.file + ":" + std::to_string(std::max(where.line, 1)) + ": " + e.what());
  }
}

Fabric compile(const Pattern& pattern, layout::Layout layout, const CompileOptions& given) {
  Fabric fabric;
  fabric.layout = std::move(layout);
  CompileOptions options = given;
  if (given.density_from_view) {
    const ViewDensity whole = density_for_view(fabric.layout);
    const bool closer = given.close_up_loop_pixels > whole.loop_pixels;
    const ViewDensity view = closer ? density_for_loop_pixels(given.close_up_loop_pixels) : whole;
    options.sides = view.density.sides;
    options.chord_tolerance = view.density.chord_tolerance;
    if (given.textures_from_view) options.textures = view.maps;
    char text[200];
    const char* maps = given.textures_from_view && given.textures && !view.maps ? " (no baked maps: their detail is under a pixel)" : "";
    if (closer) std::snprintf(text, sizeof text, "from the view: a loop spans %.0f px of the close-up%s", view.loop_pixels, maps);
    else std::snprintf(text, sizeof text, "from the view: a loop spans %.0f px of a %d x %d px full view%s", view.loop_pixels, view_width, view_height, maps);
    fabric.density_choice = text;
  } else {
    fabric.density_choice = "as given";
  }
  fabric.density = {options.sides, options.chord_tolerance};
  auto paths = yarn_paths::trace(fabric.layout, options.loop_model);
  const curves::Options curve = curve_options(options);

  // The mesh's size from the data points, before any curve is fitted or relaxed (not for
  // a fabric that may be tiled: its flat size is no reason to refuse it).
  if (!may_tile(options, pattern, fabric.layout.knitting)) {
    double estimate = 0.0;
    for (const auto& path : paths) {
      const Yarn& yarn = pattern.yarns[path.yarn];
      const auto samples = static_cast<std::size_t>(std::ceil(curves::estimate_samples(path, yarn, curve)));
      estimate += static_cast<double>(tubes::vertex_count(yarn, samples, options.sides));
    }
    if (estimate > static_cast<double>(max_vertices)) too_many_vertices(pattern, estimate, "about ");
  }

  // Relaxed by a repeat: per piece and point, the copy of the tile it repeats (relax::Relaxed).
  std::vector<std::vector<std::uint32_t>> same_as;
  if (options.relax) {
    report(options, "relax", 0.0);
    std::vector<yarn::Size> sizes;
    std::vector<double> core;
    for (const Yarn& y : pattern.yarns) {
      sizes.push_back({y.diameter, y.core_diameter});
      core.push_back(y.core_diameter);
    }
    relax::Options ro = options.relaxation;
    ro.threads = options.threads;
    const bool flat = fabric.layout.knitting == Knitting::flat;
    ro.pressed = !flat;  // flat work is pressed beside its crossings check, below
    auto laid = relax::refine(std::move(paths), core, ro.spacing, options.threads);
    auto relaxed = relax::relax(fabric.layout, laid, sizes, ro);
    // The relaxation checked by its result: did any yarn come out on the other side of
    // another (docs/relaxation.md)? Tiling jumps the yarn to the tile's places with no
    // sweep between to keep its crossings; where that passed a yarn through another, the
    // fabric is relaxed again with its edges' bands whole (not as strips) and then whole,
    // and the one that passed fewer kept.
    double thickest = 0.0;
    for (const Yarn& y : pattern.yarns) thickest = std::max(thickest, y.diameter);
    // The knot diagram seen from the face: a tube's unrolled into its flat frame.
    auto changes = [&](const relax::Relaxed& r, int threads) {
      if (flat) return measure::relaxation_changes(laid, r.pieces, thickest, threads, r.same_as);
      const relax::TubeAsFlat seen = relax::tube_as_flat(fabric.layout, laid, r.pieces);
      return measure::relaxation_changes(seen.laid, seen.relaxed, thickest, threads, r.same_as);
    };
    if (flat) {
      // Pressing writes the sections, the check reads the points: side by side, each on
      // one thread (both are mostly serial passes over every point).
      parallel_for(2, thread_count(options.threads), [&](std::size_t job) {
        if (job == 0) relax::press(relaxed.pieces, sizes, 1, relaxed.same_as);
        else fabric.crossings = changes(relaxed, 1);
      });
    } else {
      fabric.crossings = changes(relaxed, options.threads);
    }
    fabric.crossings_checked = true;
    // Relaxed again another way, kept (and pressed) if it passed fewer yarns through
    // another. Not a tube: relaxed whole it keeps no crossing's side either (the sweeps'
    // memory of them is flat work's), so it would pass no fewer, for the whole
    // relaxation's cost (mil-tube.k: 300 by repeat, no fewer whole, 35 s against 6); what
    // it passed is said, as flat work's is.
    auto retry = [&](relax::Options again, bool whole) {
      auto other = relax::relax(fabric.layout, laid, sizes, again);
      auto other_crossings = changes(other, options.threads);
      if (measure::passed_through(other_crossings) >= measure::passed_through(fabric.crossings)) return;
      relax::press(other.pieces, sizes, thread_count(options.threads), other.same_as);
      fabric.tiling_refused = whole;
      relaxed = std::move(other);
      fabric.crossings = other_crossings;
    };
    if (flat && relaxed.stats.strips > 0 && measure::passed_through(fabric.crossings) > 0) {
      relax::Options bands = ro;  // by the same repeat, the edges' bands relaxed whole
      bands.by_strips = false;
      retry(bands, false);
    }
    if (flat && relaxed.stats.repeat_wales > 0 && measure::passed_through(fabric.crossings) > 0) {
      relax::Options whole = ro;
      whole.by_repeat = false;
      retry(whole, true);
    }
    same_as = relax::same_as_by_piece(relaxed.pieces, relaxed.same_as);
    paths = std::move(relaxed.pieces);
    fabric.relaxed = true;
    fabric.relaxation = relaxed.stats;
    report(options, "relax", 1.0);
  }

  fabric.pieces.resize(paths.size());
  std::atomic<std::size_t> traced{0};
  const std::size_t step = std::max<std::size_t>(1, paths.size() / 100);
  parallel_for(paths.size(), thread_count(options.threads), [&](std::size_t i) {
    const Yarn& yarn = pattern.yarns[paths[i].yarn];
    fabric.pieces[i] = curves::trace(std::move(paths[i]), yarn, curve, same_as.empty() ? std::span<const std::uint32_t>{} : same_as[i]);
    if (const std::size_t done = ++traced; done % step == 0)
      report(options, "curves", static_cast<double>(done) / static_cast<double>(paths.size()));
  });

  // The exact size, known from the samples, before the mesh is allocated.
  std::uint64_t vertices = 0;
  for (const CurvePiece& p : fabric.pieces)
    vertices += tubes::vertex_count(pattern.yarns[p.path.yarn], p.samples.size(), options.sides);
  report(options, "mesh", 0.0);
  if (options.fibres && options.view == View::surface) {
    const std::uint64_t lines = fibres::fibre_vertices(pattern.yarns, fabric.pieces);
    if (lines + vertices > max_vertices) too_many_vertices(pattern, static_cast<double>(lines + vertices), "with its fibres ");
    fabric.mesh = fibres::build_mesh(pattern.yarns, fabric.pieces, options.sides, options.threads);
    fabric.mesh_choice = "fibres (--section fibres): " + millions(static_cast<double>(lines)) + " fibre vertices round the plies' cores";
    report(options, "mesh", 1.0);
    return fabric;
  }
  const bool by_repeat = fabric.relaxed && fabric.relaxation.repeat_wales > 0 && !fabric.tiling_refused &&
                         options.view == View::surface && fabric.layout.knitting == Knitting::flat && !dyed(pattern);
  const bool big = vertices > flat_vertices;
  const std::string flat_size = millions(static_cast<double>(vertices)) + " vertices";
  std::string declined;
  if (!by_repeat) {
    declined = options.view != View::surface             ? "only the surface is instanced"
               : fabric.layout.knitting != Knitting::flat ? "work in the round is not tiled"
               : !fabric.relaxed                          ? "not relaxed, so no repeat was tiled"
               : dyed(pattern)                            ? "a yarn dyed along its length colours no two tiles alike"
               : fabric.tiling_refused                    ? "relaxed whole (tiled, a yarn passed through another)"
                                                          : "relaxed whole, not by a repeat (none found, or its tiled start refused: docs/relaxation.md)";
  }
  if (by_repeat && (options.instancing != Instancing::automatic || big)) {
    const tiles::Lattice lattice{fabric.relaxation.repeat_wales, fabric.relaxation.repeat_courses, fabric.relaxation.repeat_wale0,
                                 fabric.relaxation.repeat_course0};
    tiles::Tiling tiled = tiles::tile(pattern.yarns, fabric.layout, fabric.pieces, lattice, options.sides, options.threads);
    if (tiled.declined.empty()) {
      const std::string cells = std::to_string(tiled.cells) + " of " + std::to_string(tiled.complete) + " whole cells of the " +
                                std::to_string(lattice.wales) + " x " + std::to_string(lattice.courses) + " repeat placed";
      if (options.instancing == Instancing::flatten) {
        const tiles::Drawn d = tiles::drawn(tiled.mesh);
        if (d.vertices > max_vertices) too_many_vertices(pattern, static_cast<double>(d.vertices), "");
        fabric.mesh = tiles::flatten(tiled.mesh, options.threads);
        if (options.textures) fibres::add_baked_textures(pattern.yarns, fabric.pieces, fabric.mesh, options.threads);
        fabric.mesh_choice = "flat (--flatten): every instance written out; " + cells;
      } else {
        fabric.mesh = std::move(tiled.mesh);
        fabric.instanced = true;
        if (options.textures) fibres::add_baked_textures(pattern.yarns, fabric.pieces, fabric.mesh, options.threads);
        fabric.mesh_choice = std::string("instanced") +
                             (options.instancing == Instancing::instance
                                  ? " (--instance)"
                                  : ": flat it would be " + flat_size + ", over the " + millions(flat_vertices) + " knitc writes flat") +
                             "; " + cells;
      }
      report(options, "mesh", 1.0);
      return fabric;
    }
    declined = tiled.declined;
  }
  if (vertices > max_vertices) too_many_vertices(pattern, static_cast<double>(vertices), "");
  if (options.instancing == Instancing::flatten) fabric.mesh_choice = "flat (--flatten): " + flat_size;
  else if (options.instancing == Instancing::instance || big) fabric.mesh_choice = "flat: " + flat_size + "; not instanced: " + declined;
  else fabric.mesh_choice = "flat: " + flat_size + ", within the " + millions(flat_vertices) + " knitc writes flat";
  fabric.mesh = tubes::build_mesh(pattern.yarns, fabric.pieces, options.view, options.sides, options.threads);
  if (options.textures && options.view == View::surface)
    fibres::add_baked_textures(pattern.yarns, fabric.pieces, fabric.mesh, options.threads);
  report(options, "mesh", 1.0);
  return fabric;
}

}  // namespace knitc
