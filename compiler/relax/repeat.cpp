#include "relax/repeat.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <map>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "parallel.hpp"
#include "relax/chains.hpp"
#include "relax/contacts.hpp"
#include "relax/strips.hpp"
#include "relax/tile.hpp"
#include "relax/tiled_start.hpp"
#include "relax/tube.hpp"
#include "spatial/columns.hpp"

namespace knitc::relax {

LoopGrid grid_of(const layout::Layout& layout) {
  LoopGrid g{layout.courses, layout.wales, {}, {}};
  if (layout.knitting == Knitting::round) g.round_needles = layout.needle;
  g.at.assign(static_cast<std::size_t>(g.courses) * static_cast<std::size_t>(g.wales), -1);
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const auto& l = layout.loops[i];
    if (l.course >= 0 && l.course < g.courses && l.wale >= 0 && l.wale < g.wales)
      g.at[static_cast<std::size_t>(l.course) * static_cast<std::size_t>(g.wales) + static_cast<std::size_t>(l.wale)] =
          static_cast<long>(i);
  }
  return g;
}

namespace {

struct Interior {
  int course_from, course_to, wale_from, wale_to;  // inclusive
};

// The smallest period along one axis at which all but a share `misses` of the interior's
// loops repeat the loop `period` on (0: every one).
int smallest_period(const layout::Layout& layout, const LoopGrid& g, const Interior& in, bool across, double misses = 0.0) {
  const int span = across ? in.wale_to - in.wale_from + 1 : in.course_to - in.course_from + 1;
  const int other = across ? in.course_to - in.course_from + 1 : in.wale_to - in.wale_from + 1;
  for (int period = 1; period <= std::min(64, span / 2); ++period) {
    const auto allowed = static_cast<std::size_t>(misses * static_cast<double>(span - period) * static_cast<double>(other));
    std::size_t missed = 0;
    for (int c = in.course_from; missed <= allowed && c <= in.course_to; ++c)
      for (int w = in.wale_from; missed <= allowed && w <= in.wale_to; ++w) {
        const int c2 = across ? c : c + period, w2 = across ? w + period : w;
        if (c2 > in.course_to || w2 > in.wale_to) continue;
        if (!repeats(layout, g(c, w), g(c2, w2), across ? period : 0, across ? 0 : period)) ++missed;
      }
    if (missed <= allowed) return period;
  }
  return 0;
}

// Whether the block of `r` and a period past it either way (within the interior) repeat
// exactly: a tile to cut where the interior mostly repeats.
bool clean_block(const layout::Layout& layout, const LoopGrid& g, const Interior& in, const Repeat& r) {
  for (int c = r.course0; c < r.course0 + r.courses + r.course_period && c <= in.course_to; ++c)
    for (int w = r.wale0; w < r.wale0 + r.wales + r.wale_period && w <= in.wale_to; ++w) {
      if (g(c, w) < 0) return false;
      if (w + r.wale_period <= in.wale_to && !repeats(layout, g(c, w), g(c, w + r.wale_period), r.wale_period, 0)) return false;
      if (c + r.course_period <= in.course_to && !repeats(layout, g(c, w), g(c + r.course_period, w), 0, r.course_period))
        return false;
    }
  return true;
}

// The interior between `below` and `above` courses more than the first and last two (and
// the first and last two needle positions of its narrowest course); none if too small to
// find a repeat in.
std::optional<Interior> interior_of(const layout::Layout& layout, int below, int above) {
  Interior in{2 + below, layout.courses - 3 - above, 2, layout.wales - 3};
  if (in.course_to - in.course_from + 1 < 8) return std::nullopt;
  for (int c = in.course_from; c <= in.course_to; ++c)
    in.wale_to = std::min(in.wale_to, layout.needle[static_cast<std::size_t>(c)] - 3);
  if (in.wale_to - in.wale_from + 1 < 4) return std::nullopt;
  return in;
}

}  // namespace

int periodic_run(const std::vector<glm::dvec3>& points, std::size_t from, std::size_t period, double width, double close) {
  if (from < run_handles || from + period + run_handles > points.size()) return 0;
  const glm::dvec3 step = points[from + period] - points[from];
  const int across = static_cast<int>(std::lround(step.x / width));
  if ((across != 1 && across != -1) || glm::distance(step, glm::dvec3(across * width, 0.0, 0.0)) >= close) return 0;
  for (std::size_t h = 1; h <= run_handles; ++h)
    if (glm::distance(points[from - h] + step, points[from + period - h]) >= close ||
        glm::distance(points[from + period + h - 1] - step, points[from + h - 1]) >= close)
      return 0;
  return across;
}

namespace {
// Whether a machine's needles set some course's positions' widths (Course::widths).
bool needles_set_widths(const layout::Layout& layout) {
  return std::find(layout.needle_widths.begin(), layout.needle_widths.end(), 1) != layout.needle_widths.end();
}
}  // namespace

double lattice_step(const layout::Layout& layout) {
  if (!needles_set_widths(layout)) return layout.loop_width;
  std::map<long long, std::pair<std::size_t, double>> widths;  // by the width in millionths of a loop width: count, a width
  for (const auto& edges : layout.slot_x)
    for (std::size_t k = 1; k < edges.size(); ++k) {
      const double w = edges[k] - edges[k - 1];
      auto& [count, width] = widths[std::llround(w / layout.loop_width * 1e6)];
      if (count++ == 0) width = w;
    }
  double step = layout.loop_width;
  std::size_t most = 0;
  for (const auto& [key, seen] : widths)
    if (seen.first > most) most = seen.first, step = seen.second;
  return step;
}

std::optional<Repeat> find_repeat(const layout::Layout& layout) {
  if (layout.courses < 8 || layout.wales < 8) return std::nullopt;
  if (layout.knitting == Knitting::round && layout.wales < least_round_wales) return std::nullopt;
  // Tucks: tiled, the held loops and the tuck loops in them lose crossings (half cardigan
  // at its own gauge: 118 lone crossings lost, docs/relaxation.md), so they relax whole.
  // Plating: two loops at each needle position, the grid's one a cell.
  for (const auto& loop : layout.loops)
    if (loop.shape == layout::Template::tuck || loop.plating) return std::nullopt;
  // Caught floats are lifted across courses to the loop that catches them, and clusters
  // narrow their needle positions, so neither lies on the lattice: relaxed whole.
  for (const auto& f : layout.floats)
    if (f.caught_by >= 0) return std::nullopt;
  if (!layout.wraps.empty()) return std::nullopt;  // a winding spans its group's loops
  if (!layout.bobbles.empty()) return std::nullopt;  // a bobble's rows share one needle position
  // Two layers: positions over each other, courses at their layers' heights.
  if (!layout.heights.empty() || layout.layer_depth > 0.0) return std::nullopt;
  if (!layout.column_y.empty()) return std::nullopt;  // short rows: columns of their own heights
  for (const auto& loop : layout.loops)  // bound off within a row: the columns change
    if (loop.shape == layout::Template::bind_off && loop.course + 1 < layout.courses) return std::nullopt;
  // Every needle position one lattice step wide (the loop width; relax() passes a machine's
  // full-needle knitting with its columns' share, Course::widths). There, only the
  // interior must lie on it: its jersey rows and cast-on are trimmed, and a column at
  // its ends that holds one bed's loop (a whole position) is left to the edges.
  auto on_lattice = [&](int from, int to, int wale_from, int wale_to) {
    for (int c = from; c <= to; ++c) {
      const auto& edges = layout.slot_x[static_cast<std::size_t>(c)];
      const auto first = static_cast<std::size_t>(std::max(wale_from, 0)) + 1;
      const std::size_t last = std::min(edges.size() - 1, static_cast<std::size_t>(wale_to) + 1);
      for (std::size_t k = first; k <= last; ++k)
        if (std::abs(edges[k] - edges[k - 1] - layout.loop_width) > 1e-9 * layout.loop_width) return false;
    }
    return true;
  };
  const bool by_needles = needles_set_widths(layout);
  if (!by_needles && !on_lattice(0, layout.courses - 1, 0, layout.wales)) return std::nullopt;
  const LoopGrid g = grid_of(layout);
  // The interior, less up to `most_trimmed` more courses at either end where those do not
  // repeat (a machine program's cast-on, its held and dropped loops, its bind-off's held
  // rows), the fewest.
  Interior in{};
  int p = 0, q = 0;
  for (int trimmed = 0; trimmed <= 2 * most_trimmed && (p == 0 || q == 0); ++trimmed)
    for (int below = std::max(0, trimmed - most_trimmed); below <= std::min(trimmed, most_trimmed) && (p == 0 || q == 0); ++below) {
      const auto trimmed_in = interior_of(layout, below, trimmed - below);
      if (!trimmed_in) continue;
      in = *trimmed_in;
      p = smallest_period(layout, g, in, true);
      q = p == 0 ? 0 : smallest_period(layout, g, in, false);
    }
  // Else the smallest period most of the whole interior repeats in (an image of knit and
  // purl whose repeat breaks where its halves meet, a motif on a plain ground): the loops
  // that do not repeat are relaxed with the edges.
  if (p == 0 || q == 0) {
    const auto whole = interior_of(layout, 0, 0);
    if (!whole) return std::nullopt;
    in = *whole;
    p = smallest_period(layout, g, in, true, most_not_repeating);
    q = p == 0 ? 0 : smallest_period(layout, g, in, false, most_not_repeating);
  }
  if (p == 0 || q == 0) return std::nullopt;
  if (by_needles && !on_lattice(in.course_from, in.course_to, in.wale_from, in.wale_to)) return std::nullopt;
  Repeat r;
  r.wales = p * ((least_tile_wales + p - 1) / p);
  r.courses = q * ((least_tile_courses + q - 1) / q);
  r.wale_period = p;
  r.course_period = q;
  // The block: the first (up, then across) that repeats exactly with a period round it.
  bool found = false;
  for (int c = in.course_from; !found && c + r.courses - 1 <= in.course_to; ++c)
    for (int w = in.wale_from; !found && w + r.wales - 1 <= in.wale_to; ++w) {
      r.course0 = c;
      r.wale0 = w;
      found = clean_block(layout, g, in, r);
    }
  if (!found) return std::nullopt;
  if (2 * static_cast<std::size_t>(r.wales * r.courses) > layout.loops.size()) return std::nullopt;
  return r;
}

std::optional<Relaxed> relax_by_repeat(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains,
                                       const std::vector<yarn::Size>& sizes, const Options& options, const Repeat& repeat) {
  const LoopGrid g = grid_of(layout);
  // A tube's tile is cut, relaxed and copied in its layout's flat frame, and every point
  // rolled back onto the tube (its stretch, the tile's, widening it and its climb).
  const bool round = layout.knitting == Knitting::round;
  const Unrolled unrolled = round ? unroll(layout, chains) : Unrolled{};
  const std::vector<yarn_paths::Piece>& flat = round ? unrolled.pieces : chains;
  std::optional<Tile> cut = cut_tile(layout, g, flat, repeat);
  if (!cut) return std::nullopt;
  const layout::Layout& tile = cut->layout;
  const std::vector<yarn_paths::Piece>& tile_pieces = cut->pieces;
  const Start& links = cut->links;

  Options tile_options = options;
  tile_options.boundary = Boundary::periodic;
  tile_options.by_repeat = false;
  // A tile is small: settled four times as far, it costs little and every loop follows it.
  tile_options.settled_motion = 0.25 * options.settled_motion;
  tile_options.max_iterations = 4 * options.max_iterations;
  // A tile's few hundred points do not pay for waking the pool's threads several times a
  // sweep: one thread relaxes it (the same result on any number).
  tile_options.threads = 1;
  // Beside the tile's relaxation (one thread), what the fabric needs made whatever the
  // tile comes to: every point's moves, none yet, which loops are tiled as which tile
  // loops (from the tile as cut), and each point's place along its yarn.
  Relaxed relaxed_tile;
  Moves moves;
  AlongYarn places;
  parallel_for(2, thread_count(options.threads), [&](std::size_t job) {
    if (job == 0) {
      relaxed_tile = relax_chains(tile, tile_pieces, sizes, tile_options, &links);
    } else {
      moves = unmoved(flat, layout.loops.size());
      tile_places(layout, g, flat, repeat, *cut, moves);
      places = along_yarn(chains, sizes);
    }
  });
  const glm::dvec2 rest_period(repeat.wales * layout.loop_width, repeat.courses * layout.course_spacing);
  if (relaxed_tile.stats.period.x <= 0.0 || relaxed_tile.stats.period.y <= 0.0) return std::nullopt;
  // A tube is not relaxed again where its yarns passed through each other (compile.cpp:
  // its whole relaxation keeps no crossing's side either): a tile that did not settle,
  // whose courses may differ where the seam sets one beside another, is not copied round
  // it.
  if (round && relaxed_tile.stats.iterations >= tile_options.max_iterations) return std::nullopt;
  const glm::dvec2 stretch = relaxed_tile.stats.period / rest_period;  // the lattice's, per axis
  // The whole fabric stretched as the tile was, about the tile's first loop's P0 (a tube
  // about its axis: x scales with the circumference).
  glm::dvec3 origin = tile.loops.front().data_points[0];
  if (round) origin.x = 0.0;
  const LatticeStretch affine{origin, stretch};
  auto stretched = [&](const glm::dvec3& p) { return p + affine(p); };  // a laid point, the fabric stretched as the tile was

  tile_moves(*cut, relaxed_tile, affine, moves);
  std::vector<std::vector<glm::dvec3>>& local = moves.local;
  const std::vector<std::vector<std::uint8_t>>& tiled = moves.tiled;
  const std::vector<std::vector<std::uint32_t>>& tile_point = moves.tile_point;
  const std::vector<std::uint32_t>& tile_first = moves.tile_first;
  const std::vector<std::uint8_t>& loop_tiled = moves.loop_tiled;

  // Held: the tiled loops with nothing untiled within the edge band, and what lies
  // between two of them along the yarn where the tile gave it (not blended).
  const HeldLoops loops_held = held_loops(layout, g, loop_tiled);
  const std::vector<std::uint8_t>& loop_held = loops_held.held;
  const std::vector<std::uint8_t>& to_free = loops_held.to_free;
  constexpr int far = far_from_free;
  Start start;
  std::vector<std::uint8_t> scan_from, scan_at;  // per point: within edge_band + 1 loops of one not held; within far
  {
    std::size_t points = 0;
    for (const auto& piece : chains) points += piece.data_points.size();
    start.held.reserve(points);
    scan_from.reserve(points);
    scan_at.reserve(points);
  }
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const auto& piece = chains[i];
    std::vector<std::uint8_t> held(piece.data_points.size(), 0), on_loop(piece.data_points.size(), 0);
    std::vector<std::uint8_t> loops_to_free(piece.data_points.size(), 0);  // 0 where between loops
    for (std::size_t j = 0; j < piece.loops.size(); ++j)
      for (std::size_t k = piece.loop_first[j]; k <= piece.loop_last[j]; ++k) {
        on_loop[k] = 1;
        held[k] = loop_held[static_cast<std::size_t>(piece.loops[j])];
        loops_to_free[k] = to_free[static_cast<std::size_t>(piece.loops[j])];
      }
    // Between two loops, the nearer of the two's; a tail, 0.
    {
      long last_on = -1;
      for (std::size_t k = 0; k <= held.size(); ++k) {
        if (k < held.size() && !on_loop[k]) continue;
        const std::uint8_t here = k < held.size() ? loops_to_free[k] : 0;
        const std::uint8_t there = last_on >= 0 ? loops_to_free[static_cast<std::size_t>(last_on)] : 0;
        for (std::size_t u = static_cast<std::size_t>(last_on + 1); u < k; ++u) loops_to_free[u] = std::min(here, there);
        last_on = static_cast<long>(k);
      }
    }
    for (const std::uint8_t d : loops_to_free) {
      scan_from.push_back(d <= edge_band + 1 ? 1 : 0);
      scan_at.push_back(d < far ? 1 : 0);
    }
    long last_on = -1;  // the last point on a loop, and whether it was held
    for (std::size_t k = 0; k < held.size(); ++k) {
      if (on_loop[k]) {
        if (held[k] && last_on >= 0 && held[static_cast<std::size_t>(last_on)])
          for (std::size_t u = static_cast<std::size_t>(last_on) + 1; u < k; ++u) held[u] = tiled[i][u];  // not if blended
        last_on = static_cast<long>(k);
      }
    }
    start.held.insert(start.held.end(), held.begin(), held.end());
    // Each point moved as the tile moved it, in place of its move (a garment's 43 MB of
    // fresh memory fewer: docs/performance.md).
    std::vector<glm::dvec3>& moved = local[i];
    parallel_for(moved.size(), thread_count(options.threads), [&](std::size_t k) {
      const glm::dvec3& p = flat[i].data_points[k];
      moved[k] += stretched(p);
      if (round) {
        const double c = unrolled.circumference[i][k];
        moved[k] = c > 0.0 ? layout::roll(moved[k], c * stretch.x, layout.course_spacing * stretch.y) : piece.data_points[k];
      }
    });
  }
  if (local.size() == 1) start.pos = std::move(local.front());  // a garment is one piece
  else {
    start.pos.reserve(start.held.size());
    for (const auto& moved : local) start.pos.insert(start.pos.end(), moved.begin(), moved.end());
  }

  // Rolled round a tube, the flat tile's inner side is pressed closer by the curvature:
  // held copies may overlap anywhere, so all are looked at, and where they do, freed.
  if (round) {
    std::fill(scan_from.begin(), scan_from.end(), std::uint8_t{1});
    std::fill(scan_at.begin(), scan_at.end(), std::uint8_t{1});
  }
  free_where_held_overlap(places, start, scan_from, scan_at, options.threads);
  places = {};
  // Tiling jumps the yarn to where the tile put it, with no sweep between to keep its
  // crossings: it must not leave the yarns deeper into each other than the layout did
  // (pushed back out, a deep overlap may come out on the wrong side). Where it would (the
  // tuck's held loops, blended over the edges), the whole fabric is relaxed instead.
  // The check, and the edges' relaxation after it, look at the edges' part of the fabric
  // only (crop): the held interior, most of a garment, lies as in the tile, and its points
  // cost nothing per sweep. Where the edges' bands form a frame, each is relaxed as a
  // strip periodic along its edge and copied along it (strips.hpp), each strip checked
  // alone; the corners are left, checked and relaxed against the copies.
  double thickest = 0.0;
  for (const auto& size : sizes) thickest = std::max(thickest, size.free_diameter);
  const double reach = 3.0 * thickest;
  std::vector<std::uint8_t> needed = near_free(start, reach, options.threads);
  const std::vector<std::uint8_t> held_by_tile = start.held;
  Strips strips = options.by_strips && !round
                      ? relax_strips(layout, chains, sizes, options, repeat, relaxed_tile.stats.period, g, loop_held, start)
                      : Strips{};
  // The interior's copies (same_as, below) are judged before the strips were held (one
  // beside a strip is not among the tile's surroundings); the strips' after.
  std::vector<std::uint8_t> needed_after = !strips.copies.empty() ? near_free(start, reach, options.threads) : needed;
  Crop part = crop(chains, start, needed_after);
  part.needed = std::move(needed);
  if (deeper_than_laid(layout, part.pieces, sizes, part.start, options.threads)) {
    // Flat work whose edges are half of it or more is relaxed whole: carried there, its
    // edges would cost about what the whole does, and where the carried yarn passes
    // through another (the compile's crossings check) it is relaxed whole after all.
    // Else it is carried to the tile's places over sweeps, from the fabric as laid,
    // stretched as the tile was. So is a tube, whose sweeps keep no crossing's side (the
    // memory is flat work's) and which is not relaxed again where a yarn passed through
    // another (compile.cpp): what its crossings check finds is said. (CMU's image tube,
    // carried, passes none through; relaxed whole it took twice as long.)
    if (2 * part.start.pos.size() > start.pos.size()) return std::nullopt;
    part.start.from.reserve(part.start.pos.size());
    for (std::size_t r = 0; r < part.pieces.size(); ++r) {
      const auto [piece, first] = part.origin[r];
      for (std::size_t k = 0; k < part.pieces[r].data_points.size(); ++k) {
        const glm::dvec3& laid = flat[piece].data_points[first + k];
        if (!round) {
          part.start.from.push_back(stretched(laid));
          continue;
        }
        // Round a tube, laid flat, stretched, and rolled onto the stretched tube, as the
        // tiled start's points are.
        const double c = unrolled.circumference[piece][first + k];
        part.start.from.push_back(c > 0.0 ? layout::roll(stretched(laid), c * stretch.x, layout.course_spacing * stretch.y)
                                          : chains[piece].data_points[first + k]);
      }
    }
    part.start.morph_sweeps = morph_sweeps;
  }
  Options edge_options = options;
  edge_options.by_repeat = false;
  Relaxed edges = relax_chains(layout, std::move(part.pieces), sizes, edge_options, &part.start);
  Relaxed out;
  out.stats = edges.stats;
  // The pieces as laid, at the tiled start's places: the start's own array where the
  // fabric is one piece (a garment's), not a copy of it.
  const std::size_t points = start.pos.size();
  out.pieces.resize(chains.size());
  for (std::size_t i = 0, at = 0; i < chains.size(); ++i) {
    const auto& laid = chains[i];
    auto& piece = out.pieces[i];
    piece.yarn = laid.yarn;
    piece.loops = laid.loops;
    piece.loop_first = laid.loop_first;
    piece.loop_last = laid.loop_last;
    piece.pressed = laid.pressed;
    const auto from = start.pos.begin() + static_cast<std::ptrdiff_t>(at);
    at += laid.data_points.size();
    if (chains.size() > 1) piece.data_points.assign(from, start.pos.begin() + static_cast<std::ptrdiff_t>(at));
  }
  if (chains.size() == 1) out.pieces.front().data_points = std::move(start.pos);
  for (std::size_t r = 0; r < edges.pieces.size(); ++r) {
    const auto [piece, at] = part.origin[r];
    std::copy(edges.pieces[r].data_points.begin(), edges.pieces[r].data_points.end(),
              out.pieces[piece].data_points.begin() + static_cast<std::ptrdiff_t>(at));
  }
  // The largest change of a whole piece's length, as relax_chains measures its pieces'.
  // Summed by blocks of steps in parallel, the blocks' sums then in order: the same for
  // any thread count.
  out.stats.length_change = 0.0;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const auto &a = chains[i].data_points, &b = out.pieces[i].data_points;
    constexpr std::size_t block = 65536;
    const std::size_t steps = a.size() > 1 ? a.size() - 1 : 0;
    std::vector<glm::dvec2> sums((steps + block - 1) / block, glm::dvec2(0.0));
    parallel_for(sums.size(), thread_count(options.threads), [&](std::size_t q) {
      for (std::size_t k = q * block + 1; k <= std::min(steps, (q + 1) * block); ++k)
        sums[q] += glm::dvec2(glm::distance(a[k - 1], a[k]), glm::distance(b[k - 1], b[k]));
    });
    double laid = 0.0, now = 0.0;
    for (const glm::dvec2& sum : sums) laid += sum.x, now += sum.y;
    if (laid > 0.0) out.stats.length_change = std::max(out.stats.length_change, std::abs(now / laid - 1.0));
  }
  // A held point that nothing free comes near (the crop's reach, three diameters: past
  // any contact's and pressing's) has its tile point's surroundings, as every other such
  // copy of it has: the first copy stands for them all. So has a strip's copy of its
  // relaxed point, every copy a whole number of periods along its edge, where nothing
  // free (a corner) comes near. (Round a tube the copies are turned, not moved: none
  // stands for another.)
  if (!round) {
    const std::uint32_t tiles = tile_first.back();
    std::vector<std::uint32_t> first_copy(tiles + strips.numbered, no_tile_point);
    std::sort(strips.copies.begin(), strips.copies.end());
    auto strip_copy = strips.copies.begin();
    out.same_as.resize(points);
    std::size_t at = 0;
    for (std::size_t i = 0; i < chains.size(); ++i)
      for (std::size_t k = 0; k < chains[i].data_points.size(); ++k, ++at) {
        out.same_as[at] = static_cast<std::uint32_t>(at);
        std::uint32_t t = no_tile_point;
        if (tile_point[i][k] != no_tile_point && held_by_tile[at] && part.needed[at] == 0) t = tile_point[i][k];
        while (strip_copy != strips.copies.end() && strip_copy->first < at) ++strip_copy;
        if (strip_copy != strips.copies.end() && strip_copy->first == at && needed_after[at] == 0) t = tiles + strip_copy->second;
        if (t == no_tile_point) continue;
        if (first_copy[t] == no_tile_point) first_copy[t] = static_cast<std::uint32_t>(at);
        out.same_as[at] = first_copy[t];
      }
  }
  out.stats.repeat_wales = repeat.wales;
  out.stats.repeat_courses = repeat.courses;
  out.stats.repeat_wale0 = repeat.wale0;
  out.stats.repeat_course0 = repeat.course0;
  out.stats.repeat_iterations = relaxed_tile.stats.iterations;
  out.stats.held_share = held_by_tile.empty() ? 0.0
                                               : static_cast<double>(std::count(held_by_tile.begin(), held_by_tile.end(), std::uint8_t{1})) /
                                                     static_cast<double>(held_by_tile.size());
  out.stats.strips = strips.relaxed;
  out.stats.strip_iterations = strips.iterations;
  out.stats.strip_share = points == 0 ? 0.0 : static_cast<double>(strips.copies.size()) / static_cast<double>(points);
  out.stats.end_overlap = std::max(out.stats.end_overlap, strips.end_overlap);
  out.stats.start_overlap = std::max(out.stats.start_overlap, relaxed_tile.stats.start_overlap);
  out.stats.morph_sweeps = part.start.morph_sweeps;
  return out;
}

}  // namespace knitc::relax
