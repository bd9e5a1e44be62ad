#include "relax/repeat.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "parallel.hpp"
#include "relax/chains.hpp"
#include "relax/contacts.hpp"
#include "relax/strips.hpp"
#include "relax/tiled_start.hpp"
#include "spatial/columns.hpp"

namespace knitc::relax {

namespace {

LoopGrid grid_of(const layout::Layout& layout) {
  LoopGrid g{layout.courses, layout.wales, {}};
  g.at.assign(static_cast<std::size_t>(g.courses) * static_cast<std::size_t>(g.wales), -1);
  for (std::size_t i = 0; i < layout.loops.size(); ++i) {
    const auto& l = layout.loops[i];
    if (l.course >= 0 && l.course < g.courses && l.wale >= 0 && l.wale < g.wales)
      g.at[static_cast<std::size_t>(l.course) * static_cast<std::size_t>(g.wales) + static_cast<std::size_t>(l.wale)] =
          static_cast<long>(i);
  }
  return g;
}

// Whether loop b is laid out as loop a moved by (wales, courses) of the lattice: the same
// stitch, shape, yarn and direction, and every data point moved by the same step.
bool repeats(const layout::Layout& layout, long a, long b, int wales, int courses) {
  if (a < 0 || b < 0) return a == b;
  const auto& la = layout.loops[static_cast<std::size_t>(a)];
  const auto& lb = layout.loops[static_cast<std::size_t>(b)];
  if (la.stitch != lb.stitch || la.shape != lb.shape || la.yarn != lb.yarn ||
      layout.direction[static_cast<std::size_t>(la.course)] != layout.direction[static_cast<std::size_t>(lb.course)])
    return false;
  const glm::dvec3 step(wales * layout.loop_width, courses * layout.course_spacing, 0.0);
  const double tolerance = 1e-6 * layout.loop_width;
  for (int k = 0; k < layout::loop_points; ++k) {
    const auto K = static_cast<std::size_t>(k);
    if (glm::distance(la.data_points[K] + step, lb.data_points[K]) > tolerance) return false;
  }
  return true;
}

struct Interior {
  int course_from, course_to, wale_from, wale_to;  // inclusive
};

// The smallest period along one axis: every interior loop repeats `period` loops on.
int smallest_period(const layout::Layout& layout, const LoopGrid& g, const Interior& in, bool across) {
  const int span = across ? in.wale_to - in.wale_from + 1 : in.course_to - in.course_from + 1;
  for (int period = 1; period <= std::min(64, span / 2); ++period) {
    bool all = true;
    for (int c = in.course_from; all && c <= in.course_to; ++c)
      for (int w = in.wale_from; all && w <= in.wale_to; ++w) {
        const int c2 = across ? c : c + period, w2 = across ? w + period : w;
        if (c2 > in.course_to || w2 > in.wale_to) continue;
        all = repeats(layout, g(c, w), g(c2, w2), across ? period : 0, across ? 0 : period);
      }
    if (all) return period;
  }
  return 0;
}

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

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

std::optional<Repeat> find_repeat(const layout::Layout& layout) {
  if (layout.knitting != Knitting::flat || layout.courses < 8 || layout.wales < 8) return std::nullopt;
  // Tucks: tiled, the held loops and the tuck loops in them lose crossings (half cardigan
  // at its own gauge: 118 lone crossings lost, docs/relaxation.md), so they relax whole.
  for (const auto& loop : layout.loops)
    if (loop.shape == layout::Template::tuck) return std::nullopt;
  // Caught floats are lifted across courses to the loop that catches them, and clusters
  // narrow their needle positions, so neither lies on the lattice: relaxed whole.
  for (const auto& f : layout.floats)
    if (f.caught_by >= 0) return std::nullopt;
  if (!layout.wraps.empty()) return std::nullopt;  // a winding spans its group's loops
  if (!layout.bobbles.empty()) return std::nullopt;  // a bobble's rows share one needle position
  for (const auto& loop : layout.loops)  // bound off within a row: the columns change
    if (loop.shape == layout::Template::bind_off && loop.course + 1 < layout.courses) return std::nullopt;
  for (const auto& edges : layout.slot_x)
    for (std::size_t k = 1; k < edges.size(); ++k)
      if (std::abs(edges[k] - edges[k - 1] - layout.loop_width) > 1e-9 * layout.loop_width) return std::nullopt;
  const LoopGrid g = grid_of(layout);
  const Interior in{2, layout.courses - 3, 2, layout.wales - 3};
  const int p = smallest_period(layout, g, in, true), q = smallest_period(layout, g, in, false);
  if (p == 0 || q == 0) return std::nullopt;
  Repeat r;
  r.wales = p * ((least_tile + p - 1) / p);
  r.courses = q * ((least_tile + q - 1) / q);
  r.wale0 = in.wale_from;
  r.course0 = in.course_from;
  if (r.wale0 + r.wales - 1 > in.wale_to || r.course0 + r.courses - 1 > in.course_to) return std::nullopt;
  for (int c = r.course0; c < r.course0 + r.courses; ++c)
    for (int w = r.wale0; w < r.wale0 + r.wales; ++w)
      if (g(c, w) < 0) return std::nullopt;
  if (2 * static_cast<std::size_t>(r.wales * r.courses) > layout.loops.size()) return std::nullopt;
  return r;
}

std::optional<Relaxed> relax_by_repeat(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains,
                                       const std::vector<yarn::Size>& sizes, const Options& options, const Repeat& repeat) {
  const LoopGrid g = grid_of(layout);
  // Which piece, and which of its loops, each loop is.
  std::vector<std::pair<long, long>> owner(layout.loops.size(), {-1, -1});
  for (std::size_t i = 0; i < chains.size(); ++i)
    for (std::size_t j = 0; j < chains[i].loops.size(); ++j)
      owner[static_cast<std::size_t>(chains[i].loops[j])] = {static_cast<long>(i), static_cast<long>(j)};

  // The tile: the block's loops as a layout of their own, and each piece's runs of them
  // (consecutive loops of one course, with what lies between them) as its pieces.
  layout::Layout tile;
  tile.courses = repeat.courses;
  tile.wales = repeat.wales;
  tile.knitting = Knitting::flat;
  tile.loop_width = layout.loop_width;
  tile.course_spacing = layout.course_spacing;
  tile.float_behind = layout.float_behind;
  tile.float_in_front = layout.float_in_front;
  std::vector<long> tile_loop(layout.loops.size(), -1);  // fabric loop -> tile loop
  for (int c = 0; c < repeat.courses; ++c) {
    const int course = repeat.course0 + c;
    tile.needle.push_back(repeat.wales);
    tile.origin_x.push_back(layout.origin_x[static_cast<std::size_t>(course)]);
    const auto& edges = layout.slot_x[static_cast<std::size_t>(course)];
    tile.slot_x.emplace_back(edges.begin() + repeat.wale0, edges.begin() + repeat.wale0 + repeat.wales + 1);
    tile.direction.push_back(layout.direction[static_cast<std::size_t>(course)]);
    for (int w = 0; w < repeat.wales; ++w) {
      const auto i = static_cast<std::size_t>(g(course, repeat.wale0 + w));
      if (owner[i].first < 0) return std::nullopt;
      layout::Loop loop = layout.loops[i];
      loop.course = c;
      loop.wale = w;
      tile_loop[i] = static_cast<long>(tile.loops.size());
      tile.loops.push_back(loop);
    }
  }
  std::vector<yarn_paths::Piece> tile_pieces;
  struct RunImage {
    std::size_t piece;
    std::uint32_t point, source;
    std::int8_t across;
  };
  std::vector<RunImage> run_images;
  std::vector<std::size_t> run_period_end;  // per tile piece: where its image a period on starts (0: none)
  std::vector<std::pair<std::size_t, std::size_t>> where_in_tile(tile.loops.size());  // tile loop -> piece, loop
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const auto& piece = chains[i];
    std::size_t j = 0;
    while (j < piece.loops.size()) {
      if (tile_loop[static_cast<std::size_t>(piece.loops[j])] < 0) {
        ++j;
        continue;
      }
      const int course = layout.loops[static_cast<std::size_t>(piece.loops[j])].course;
      std::size_t end = j + 1;
      while (end < piece.loops.size() && tile_loop[static_cast<std::size_t>(piece.loops[end])] >= 0 &&
             layout.loops[static_cast<std::size_t>(piece.loops[end])].course == course)
        ++end;
      // One period of the course's yarn, [from, from + n), and `handles` points on each
      // side of it: its images in the tiles before and after, kept there as it moves.
      std::size_t from = piece.loop_first[j], n = piece.loop_last[end - 1] + 1 - from, handles = 0;
      int across = 0;
      const bool neighbours = j > 0 && end < piece.loops.size() &&
                              layout.loops[static_cast<std::size_t>(piece.loops[j - 1])].course == course &&
                              layout.loops[static_cast<std::size_t>(piece.loops[end])].course == course;
      if (neighbours) {
        const std::size_t period = piece.loop_first[end] - from;
        across = periodic_run(piece.data_points, from, period, repeat.wales * layout.loop_width, 1e-3 * layout.loop_width);
        if (across != 0) {
          n = period;
          handles = run_handles;
        }
      }
      yarn_paths::Piece run;
      run.yarn = piece.yarn;
      run.data_points.assign(piece.data_points.begin() + static_cast<std::ptrdiff_t>(from - handles),
                             piece.data_points.begin() + static_cast<std::ptrdiff_t>(from + n + handles));
      const std::size_t base = from - handles;
      for (std::size_t k = j; k < end; ++k) {
        const auto t = static_cast<std::size_t>(tile_loop[static_cast<std::size_t>(piece.loops[k])]);
        where_in_tile[t] = {tile_pieces.size(), run.loops.size()};
        run.loops.push_back(static_cast<int>(t));
        run.loop_first.push_back(piece.loop_first[k] - base);
        run.loop_last.push_back(piece.loop_last[k] - base);
      }
      for (std::size_t h = 0; h < handles; ++h) {  // in the run's own indices; made global below
        run_images.push_back({tile_pieces.size(), static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h + n),
                              static_cast<std::int8_t>(-across)});
        run_images.push_back({tile_pieces.size(), static_cast<std::uint32_t>(handles + n + h), static_cast<std::uint32_t>(handles + h),
                              static_cast<std::int8_t>(across)});
      }
      tile_pieces.push_back(std::move(run));
      run_period_end.push_back(handles > 0 ? handles + n : 0);
      j = end;
    }
  }

  Options tile_options = options;
  tile_options.boundary = Boundary::periodic;
  tile_options.by_repeat = false;
  // A tile is small: settled four times as far, it costs little and every loop follows it.
  tile_options.settled_motion = 0.25 * options.settled_motion;
  tile_options.max_iterations = 4 * options.max_iterations;
  Start links;
  {
    std::vector<std::uint32_t> first(tile_pieces.size() + 1, 0);
    for (std::size_t t = 0; t < tile_pieces.size(); ++t)
      first[t + 1] = first[t] + static_cast<std::uint32_t>(tile_pieces[t].data_points.size());
    for (const RunImage& r : run_images)
      links.images.push_back({first[r.piece] + r.point, first[r.piece] + r.source, r.across});
  }
  const Relaxed relaxed_tile = relax_chains(tile, tile_pieces, sizes, tile_options, &links);
  const glm::dvec2 rest_period(repeat.wales * layout.loop_width, repeat.courses * layout.course_spacing);
  if (relaxed_tile.stats.period.x <= 0.0 || relaxed_tile.stats.period.y <= 0.0) return std::nullopt;
  const glm::dvec2 stretch = relaxed_tile.stats.period / rest_period;  // the lattice's, per axis
  // The whole fabric stretched as the tile was, about the tile's first loop's P0.
  const glm::dvec3 origin = tile.loops.front().data_points[0];
  auto affine = [&](const glm::dvec3& p) {
    return glm::dvec3((p.x - origin.x) * (stretch.x - 1.0), (p.y - origin.y) * (stretch.y - 1.0), 0.0);
  };

  // Every point's own move (over the lattice's stretch): a tiled loop's is its tile
  // loop's; the others' are blended along their yarn between the nearest tiled points.
  std::vector<std::vector<glm::dvec3>> local(chains.size());
  std::vector<std::vector<std::uint8_t>> tiled(chains.size());
  // Per tiled point, its tile point (the tile's pieces' points in order).
  constexpr std::uint32_t none = UINT32_MAX;
  std::vector<std::vector<std::uint32_t>> tile_point(chains.size());
  std::vector<std::uint32_t> tile_first(tile_pieces.size() + 1, 0);
  for (std::size_t t = 0; t < tile_pieces.size(); ++t)
    tile_first[t + 1] = tile_first[t] + static_cast<std::uint32_t>(tile_pieces[t].data_points.size());
  std::vector<std::uint8_t> loop_tiled(layout.loops.size(), 0);
  for (std::size_t i = 0; i < chains.size(); ++i) {
    local[i].assign(chains[i].data_points.size(), glm::dvec3(0.0));
    tiled[i].assign(chains[i].data_points.size(), 0);
    tile_point[i].assign(chains[i].data_points.size(), none);
  }
  // The loop the tile has in each loop's place, and whether it is laid out as that one.
  auto tile_place = [&](const layout::Loop& loop) {
    const int dc = loop.course - repeat.course0, dw = loop.wale - repeat.wale0;
    return glm::ivec2(dw - floor_div(dw, repeat.wales) * repeat.wales, dc - floor_div(dc, repeat.courses) * repeat.courses);
  };
  std::vector<std::uint8_t> as_tiled(layout.loops.size(), 0);
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    const glm::ivec2 t = tile_place(loop);
    as_tiled[l] = repeats(layout, g(repeat.course0 + t.y, repeat.wale0 + t.x), static_cast<long>(l), loop.wale - (repeat.wale0 + t.x),
                          loop.course - (repeat.course0 + t.y));
  }
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    const auto [pi, pj] = owner[l];
    if (pi < 0 || !as_tiled[l]) continue;
    const glm::ivec2 place = tile_place(loop);
    const long cls = g(repeat.course0 + place.y, repeat.wale0 + place.x);
    // Tiled only where the loop and its neighbours two loops round are each laid out as
    // their tile loops: the tile's shape then fits among them (a selvedge loop, or one
    // beside a band of another stitch, is not).
    bool alike_round = true;
    for (int u = -2; alike_round && u <= 2; ++u)
      for (int v = -2; alike_round && v <= 2; ++v) {
        const long other = g(loop.course + u, loop.wale + v);
        alike_round = other >= 0 && as_tiled[static_cast<std::size_t>(other)];
      }
    if (!alike_round) continue;
    const auto t = static_cast<std::size_t>(tile_loop[static_cast<std::size_t>(cls)]);
    const auto [tp, tj] = where_in_tile[t];
    const auto& fabric_piece = chains[static_cast<std::size_t>(pi)];
    const auto& rest_run = tile_pieces[tp];
    const auto& relaxed_run = relaxed_tile.pieces[tp];
    const auto J = static_cast<std::size_t>(pj);
    const std::size_t f = fabric_piece.loop_first[J], tf = rest_run.loop_first[tj];
    if (rest_run.loop_last[tj] - tf != fabric_piece.loop_last[J] - f) continue;
    // The loop's points, and those on to the next loop's first (the yarn between a knit
    // and a purl, a float) when the tile has as many there: in the tile the next loop is
    // the run's next, or the image of its first a period on.
    std::size_t n = fabric_piece.loop_last[J] - f;
    const std::size_t tile_next = tj + 1 < rest_run.loops.size() ? rest_run.loop_first[tj + 1] : run_period_end[tp];
    // Laid out alike, the tile's points the fabric's moved by a lattice step.
    const glm::dvec3 shift = fabric_piece.data_points[f] - rest_run.data_points[tf];
    // (The refined points of a loop near a selvedge stray a little from its tile loop's:
    // the interpolation is global. The yarn between loops must be the tile's closely.)
    auto alike = [&](std::size_t from, std::size_t to, double tolerance) {
      for (std::size_t k = from; k <= to; ++k)
        if (glm::distance(fabric_piece.data_points[f + k], rest_run.data_points[tf + k] + shift) > tolerance * layout.loop_width)
          return false;
      return true;
    };
    if (!alike(0, n, 1e-2)) continue;
    if (J + 1 < fabric_piece.loops.size() && tile_next > tf + n && tile_next <= rest_run.data_points.size() &&
        fabric_piece.loop_first[J + 1] - f == tile_next - tf && alike(n + 1, tile_next - tf - 1, 1e-3))
      n = tile_next - tf - 1;
    for (std::size_t k = 0; k <= n; ++k) {
      const glm::dvec3& at = rest_run.data_points[tf + k];
      local[static_cast<std::size_t>(pi)][f + k] = relaxed_run.data_points[tf + k] - at - affine(at);
      tiled[static_cast<std::size_t>(pi)][f + k] = 1;
      tile_point[static_cast<std::size_t>(pi)][f + k] = tile_first[tp] + static_cast<std::uint32_t>(tf + k);
    }
    loop_tiled[l] = 1;
  }
  for (std::size_t i = 0; i < chains.size(); ++i) {
    auto& move = local[i];
    const auto& mark = tiled[i];
    long last = -1;
    for (std::size_t k = 0; k <= move.size(); ++k) {
      if (k < move.size() && !mark[k]) continue;
      // Points last+1 .. k-1 lie between tiled points last and k (either may be missing).
      for (long u = last + 1; u < static_cast<long>(k); ++u) {
        const auto U = static_cast<std::size_t>(u);
        if (last >= 0 && k < move.size()) {
          const double t = static_cast<double>(u - last) / static_cast<double>(static_cast<long>(k) - last);
          move[U] = (1.0 - t) * move[static_cast<std::size_t>(last)] + t * move[k];
        } else if (last >= 0) {
          move[U] = move[static_cast<std::size_t>(last)];
        } else if (k < move.size()) {
          move[U] = move[k];
        }
      }
      last = static_cast<long>(k);
    }
  }

  // Held: the tiled loops with nothing untiled within the edge band, and what lies
  // between two of them along the yarn where the tile gave it (not blended).
  std::vector<std::uint8_t> loop_held(layout.loops.size(), 0);
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    if (!loop_tiled[l]) continue;
    bool inside = true;
    const auto& loop = layout.loops[l];
    for (int dc = -edge_band; inside && dc <= edge_band; ++dc)
      for (int dw = -edge_band; inside && dw <= edge_band; ++dw) {
        const long other = g(loop.course + dc, loop.wale + dw);
        inside = other >= 0 && loop_tiled[static_cast<std::size_t>(other)];
      }
    loop_held[l] = inside ? 1 : 0;
  }
  // Per loop, how many loops (across or up, at most `far`) the nearest loop not held is
  // (or a place with no loop): a distance transform, along the courses, then up.
  constexpr int far = edge_band + 3;
  std::vector<std::uint8_t> to_free(layout.loops.size(), far);
  {
    const int C = g.courses, W = g.wales;
    auto at = [&](int c, int w) { return static_cast<std::size_t>(c) * static_cast<std::size_t>(W) + static_cast<std::size_t>(w); };
    std::vector<int> along(static_cast<std::size_t>(C) * static_cast<std::size_t>(W));
    for (int c = 0; c < C; ++c) {
      for (int w = 0; w < W; ++w) {
        const long l = g(c, w);
        along[at(c, w)] = l < 0 || !loop_held[static_cast<std::size_t>(l)] ? 0 : std::min(far, w > 0 ? along[at(c, w - 1)] + 1 : 1);
      }
      for (int w = W - 1; w >= 0; --w) along[at(c, w)] = std::min(along[at(c, w)], w + 1 < W ? along[at(c, w + 1)] + 1 : 1);
    }
    for (int c = 0; c < C; ++c)
      for (int w = 0; w < W; ++w) {
        const long l = g(c, w);
        if (l < 0) continue;
        int d = far;
        for (int dc = -far; dc <= far; ++dc) {
          const int cc = c + dc;
          d = std::min(d, cc < 0 || cc >= C ? std::abs(dc) : std::max(std::abs(dc), along[at(cc, w)]));
        }
        to_free[static_cast<std::size_t>(l)] = static_cast<std::uint8_t>(d);
      }
  }
  Start start;
  std::vector<std::uint8_t> scan_from, scan_at;  // per point: within edge_band + 1 loops of one not held; within far
  {
    std::size_t points = 0;
    for (const auto& piece : chains) points += piece.data_points.size();
    start.pos.reserve(points);
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
    for (std::size_t k = 0; k < held.size(); ++k) {
      const glm::dvec3& p = piece.data_points[k];
      start.pos.push_back(p + affine(p) + local[i][k]);
      start.held.push_back(held[k]);
    }
  }

  free_where_held_overlap(chains, sizes, start, scan_from, scan_at, options.threads);
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
  std::vector<std::uint8_t> needed = near_free(start, reach);
  const std::vector<std::uint8_t> held_by_tile = start.held;
  const Strips strips = options.by_strips
                            ? relax_strips(layout, chains, sizes, options, repeat, relaxed_tile.stats.period, g, loop_held, start)
                            : Strips{};
  if (strips.refused) return std::nullopt;
  // The interior's copies (same_as, below) are judged before the strips were held.
  Crop part = crop(chains, start, strips.points > 0 ? near_free(start, reach) : needed);
  part.needed = std::move(needed);
  if (deeper_than_laid(layout, part.pieces, sizes, part.start, options.threads)) return std::nullopt;
  Options edge_options = options;
  edge_options.by_repeat = false;
  Relaxed edges = relax_chains(layout, std::move(part.pieces), sizes, edge_options, &part.start);
  Relaxed out;
  out.stats = edges.stats;
  out.pieces = chains;
  {
    std::size_t at = 0;
    for (auto& piece : out.pieces)
      for (auto& p : piece.data_points) p = start.pos[at++];
  }
  for (std::size_t r = 0; r < edges.pieces.size(); ++r) {
    const auto [piece, at] = part.origin[r];
    std::copy(edges.pieces[r].data_points.begin(), edges.pieces[r].data_points.end(),
              out.pieces[piece].data_points.begin() + static_cast<std::ptrdiff_t>(at));
  }
  // The largest change of a whole piece's length, as relax_chains measures its pieces'.
  out.stats.length_change = 0.0;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    double laid = 0.0, now = 0.0;
    for (std::size_t k = 1; k < chains[i].data_points.size(); ++k) {
      laid += glm::distance(chains[i].data_points[k - 1], chains[i].data_points[k]);
      now += glm::distance(out.pieces[i].data_points[k - 1], out.pieces[i].data_points[k]);
    }
    if (laid > 0.0) out.stats.length_change = std::max(out.stats.length_change, std::abs(now / laid - 1.0));
  }
  // A held point that nothing free comes near (the crop's reach, three diameters: past
  // any contact's and pressing's) has its tile point's surroundings, as every other such
  // copy of it has: the first copy stands for them all.
  {
    std::vector<std::uint32_t> first_copy(tile_first.back(), none);
    out.same_as.resize(start.pos.size());
    std::size_t at = 0;
    for (std::size_t i = 0; i < chains.size(); ++i)
      for (std::size_t k = 0; k < chains[i].data_points.size(); ++k, ++at) {
        out.same_as[at] = static_cast<std::uint32_t>(at);
        const std::uint32_t t = tile_point[i][k];
        if (t == none || !held_by_tile[at] || part.needed[at] != 0) continue;
        if (first_copy[t] == none) first_copy[t] = static_cast<std::uint32_t>(at);
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
  out.stats.strip_share = start.pos.empty() ? 0.0 : static_cast<double>(strips.points) / static_cast<double>(start.pos.size());
  out.stats.end_overlap = std::max(out.stats.end_overlap, strips.end_overlap);
  out.stats.start_overlap = std::max(out.stats.start_overlap, relaxed_tile.stats.start_overlap);
  return out;
}

}  // namespace knitc::relax
