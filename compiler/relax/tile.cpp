// The tile cut from the fabric, and each point's move from its relaxation (tile.hpp).
#include "relax/tile.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

namespace knitc::relax {

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

std::optional<Tile> cut_tile(const layout::Layout& layout, const LoopGrid& g, const std::vector<yarn_paths::Piece>& chains,
                             const Repeat& repeat) {
  Tile out;
  auto& owner = out.owner;
  auto& tile = out.layout;
  auto& tile_loop = out.tile_loop;
  auto& tile_pieces = out.pieces;
  auto& where_in_tile = out.where_in_tile;
  auto& run_period_end = out.run_period_end;
  auto& links = out.links;
  // Which piece, and which of its loops, each loop is.
  owner.assign(layout.loops.size(), {-1, -1});
  for (std::size_t i = 0; i < chains.size(); ++i)
    for (std::size_t j = 0; j < chains[i].loops.size(); ++j)
      owner[static_cast<std::size_t>(chains[i].loops[j])] = {static_cast<long>(i), static_cast<long>(j)};

  // The tile: the block's loops as a layout of their own, and each piece's runs of them
  // (consecutive loops of one course, with what lies between them) as its pieces.
  tile.courses = repeat.courses;
  tile.wales = repeat.wales;
  tile.knitting = Knitting::flat;
  tile.loop_width = layout.loop_width;
  tile.course_spacing = layout.course_spacing;
  tile.float_behind = layout.float_behind;
  tile.float_in_front = layout.float_in_front;
  tile_loop.assign(layout.loops.size(), -1);
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
  struct RunImage {
    std::size_t piece;
    std::uint32_t point, source;
    std::int8_t across;
  };
  std::vector<RunImage> run_images;
  where_in_tile.assign(tile.loops.size(), {0, 0});
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

  {
    std::vector<std::uint32_t> first(tile_pieces.size() + 1, 0);
    for (std::size_t t = 0; t < tile_pieces.size(); ++t)
      first[t + 1] = first[t] + static_cast<std::uint32_t>(tile_pieces[t].data_points.size());
    for (const RunImage& r : run_images)
      links.images.push_back({first[r.piece] + r.point, first[r.piece] + r.source, r.across});
  }
  return out;
}

Moves unmoved(const std::vector<yarn_paths::Piece>& chains, std::size_t loops) {
  Moves out;
  out.local.resize(chains.size());
  out.tiled.resize(chains.size());
  out.tile_point.resize(chains.size());
  for (std::size_t i = 0; i < chains.size(); ++i) {
    out.local[i].assign(chains[i].data_points.size(), glm::dvec3(0.0));
    out.tiled[i].assign(chains[i].data_points.size(), 0);
    out.tile_point[i].assign(chains[i].data_points.size(), no_tile_point);
  }
  out.loop_tiled.assign(loops, 0);
  return out;
}

void tile_places(const layout::Layout& layout, const LoopGrid& g, const std::vector<yarn_paths::Piece>& chains, const Repeat& repeat,
                 const Tile& cut, Moves& out) {
  auto& tiled = out.tiled;
  auto& tile_point = out.tile_point;
  auto& tile_first = out.tile_first;
  auto& loop_tiled = out.loop_tiled;
  assert(tiled.size() == chains.size() && loop_tiled.size() == layout.loops.size());
  const std::vector<yarn_paths::Piece>& tile_pieces = cut.pieces;
  const std::vector<long>& tile_loop = cut.tile_loop;
  tile_first.assign(tile_pieces.size() + 1, 0);
  for (std::size_t t = 0; t < tile_pieces.size(); ++t)
    tile_first[t + 1] = tile_first[t] + static_cast<std::uint32_t>(tile_pieces[t].data_points.size());
  // The loop the tile has in each loop's place, and whether it is laid out as that one.
  auto tile_place = [&](const layout::Loop& loop) {
    const int dc = loop.course - repeat.course0, dw = loop.wale - repeat.wale0;
    return glm::ivec2(in_period(dw, repeat.wales), in_period(dc, repeat.courses));
  };
  // Each loop's place in the tile: its place on the lattice where it and its neighbours
  // two loops round are laid out as their tile loops there. Past a break in a mostly
  // repeating interior the repeat runs on shifted, by one shift for the whole run: there,
  // the lattice place moved by the least shift (up, then across) at which the loop and
  // its neighbours are (one that fits the loop alone may not fit them: a diagonal's loops
  // each fit several places). Else, as before any shift was looked for, the lattice place
  // if the loop alone is laid out as its loop, or the first place that is; none if none is.
  std::vector<std::uint8_t> as_tiled(layout.loops.size(), 0);
  std::vector<glm::ivec2> place_of(layout.loops.size(), glm::ivec2(0));
  auto laid_as = [&](const layout::Loop& loop, std::size_t l, glm::ivec2 t) {
    return repeats(layout, g(repeat.course0 + t.y, repeat.wale0 + t.x), static_cast<long>(l), loop.wale - (repeat.wale0 + t.x),
                   loop.course - (repeat.course0 + t.y));
  };
  auto shifted = [&](const layout::Loop& loop, glm::ivec2 shift) {
    const glm::ivec2 t = tile_place(loop) + shift;
    return glm::ivec2(in_period(t.x, repeat.wales), in_period(t.y, repeat.courses));
  };
  std::vector<std::uint8_t> on_lattice(layout.loops.size(), 0);
  for (std::size_t l = 0; l < layout.loops.size(); ++l) on_lattice[l] = laid_as(layout.loops[l], l, tile_place(layout.loops[l]));
  auto fits_round = [&](const layout::Loop& loop, glm::ivec2 shift) {
    for (int u = -2; u <= 2; ++u)
      for (int v = -2; v <= 2; ++v) {
        const long other = g(loop.course + u, loop.wale + v);
        if (other < 0) return false;
        const auto o = static_cast<std::size_t>(other);
        if (shift == glm::ivec2(0) ? !on_lattice[o] : !laid_as(layout.loops[o], o, shifted(layout.loops[o], shift))) return false;
      }
    return true;
  };
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    place_of[l] = tile_place(loop);
    as_tiled[l] = on_lattice[l];
    if (on_lattice[l] && fits_round(loop, glm::ivec2(0))) continue;
    bool found = false;
    for (int y = 0; !found && y < repeat.courses; ++y)
      for (int x = 0; !found && x < repeat.wales; ++x) {
        const glm::ivec2 shift(x, y);
        if (shift == glm::ivec2(0) || !laid_as(loop, l, shifted(loop, shift)) || !fits_round(loop, shift)) continue;
        place_of[l] = shifted(loop, shift);
        as_tiled[l] = 1;
        found = true;
      }
    for (int y = 0; !as_tiled[l] && y < repeat.courses; ++y)
      for (int x = 0; !as_tiled[l] && x < repeat.wales; ++x)
        if (laid_as(loop, l, glm::ivec2(x, y))) {
          place_of[l] = glm::ivec2(x, y);
          as_tiled[l] = 1;
        }
  }
  for (std::size_t l = 0; l < layout.loops.size(); ++l) {
    const auto& loop = layout.loops[l];
    const auto [pi, pj] = cut.owner[l];
    if (pi < 0 || !as_tiled[l]) continue;
    const glm::ivec2 place = place_of[l];
    const long cls = g(repeat.course0 + place.y, repeat.wale0 + place.x);
    // Tiled only where the loop and its neighbours two loops round are each laid out as
    // their tile loops, and are the repeat's neighbours there: the tile's shape then fits
    // among them (a selvedge loop, or one beside a band of another stitch, is not; nor,
    // round a tube, one whose neighbour past the round's start is not the repeat's).
    bool alike_round = true;
    for (int u = -2; alike_round && u <= 2; ++u)
      for (int v = -2; alike_round && v <= 2; ++v) {
        const long other = g(loop.course + u, loop.wale + v);
        if (other < 0 || !as_tiled[static_cast<std::size_t>(other)]) {
          alike_round = false;
          continue;
        }
        const glm::ivec2 there = place_of[static_cast<std::size_t>(other)];
        alike_round = in_period(there.x, repeat.wale_period) == in_period(place.x + v, repeat.wale_period) &&
                      in_period(there.y, repeat.course_period) == in_period(place.y + u, repeat.course_period);
      }
    if (!alike_round) continue;
    const auto t = static_cast<std::size_t>(tile_loop[static_cast<std::size_t>(cls)]);
    const auto [tp, tj] = cut.where_in_tile[t];
    const auto& fabric_piece = chains[static_cast<std::size_t>(pi)];
    const auto& rest_run = tile_pieces[tp];
    const auto J = static_cast<std::size_t>(pj);
    const std::size_t f = fabric_piece.loop_first[J], tf = rest_run.loop_first[tj];
    if (rest_run.loop_last[tj] - tf != fabric_piece.loop_last[J] - f) continue;
    // The loop's points, and those on to the next loop's first (the yarn between a knit
    // and a purl, a float) when the tile has as many there: in the tile the next loop is
    // the run's next, or the image of its first a period on.
    std::size_t n = fabric_piece.loop_last[J] - f;
    const std::size_t tile_next = tj + 1 < rest_run.loops.size() ? rest_run.loop_first[tj + 1] : cut.run_period_end[tp];
    // Laid out alike, the tile's points the fabric's moved by a lattice step (taken at the
    // loop's middle: a tube's point where one round meets the next may be unrolled a
    // round away, as its other loop's, and is alike a round's step from the tile's).
    const glm::dvec3 shift = fabric_piece.data_points[f + n / 2] - rest_run.data_points[tf + n / 2];
    const glm::dvec3 round_step = layout.knitting == Knitting::round
                                      ? glm::dvec3(layout::course_width(layout, loop.course), layout.course_spacing, 0.0)
                                      : glm::dvec3(0.0);
    // (The refined points of a loop near a selvedge stray a little from its tile loop's:
    // the interpolation is global. The yarn between loops must be the tile's closely.)
    auto alike = [&](std::size_t from, std::size_t to, double tolerance) {
      for (std::size_t k = from; k <= to; ++k) {
        glm::dvec3 off = fabric_piece.data_points[f + k] - (rest_run.data_points[tf + k] + shift);
        if (round_step.x > 0.0) off -= std::round(off.x / round_step.x) * round_step;
        if (glm::length(off) > tolerance * layout.loop_width) return false;
      }
      return true;
    };
    if (!alike(0, n, 1e-2)) continue;
    if (J + 1 < fabric_piece.loops.size() && tile_next > tf + n && tile_next <= rest_run.data_points.size() &&
        fabric_piece.loop_first[J + 1] - f == tile_next - tf && alike(n + 1, tile_next - tf - 1, 1e-3))
      n = tile_next - tf - 1;
    for (std::size_t k = 0; k <= n; ++k) {
      tiled[static_cast<std::size_t>(pi)][f + k] = 1;
      tile_point[static_cast<std::size_t>(pi)][f + k] = tile_first[tp] + static_cast<std::uint32_t>(tf + k);
    }
    out.spans.push_back({static_cast<std::uint32_t>(pi), static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(n + 1),
                         static_cast<std::uint32_t>(tp), static_cast<std::uint32_t>(tf)});
    loop_tiled[l] = 1;
  }
}

void tile_moves(const Tile& cut, const Relaxed& relaxed_tile, const LatticeStretch& affine, Moves& out) {
  auto& local = out.local;
  const auto& tiled = out.tiled;
  for (const Moves::Span& s : out.spans) {
    const auto& rest_run = cut.pieces[s.run];
    const auto& relaxed_run = relaxed_tile.pieces[s.run];
    for (std::size_t k = 0; k < s.count; ++k) {
      const glm::dvec3& at = rest_run.data_points[s.run_first + k];
      local[s.piece][s.first + k] = relaxed_run.data_points[s.run_first + k] - at - affine(at);
    }
  }
  for (std::size_t i = 0; i < local.size(); ++i) {
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
}

HeldLoops held_loops(const layout::Layout& layout, const LoopGrid& g, const std::vector<std::uint8_t>& loop_tiled) {
  HeldLoops out;
  std::vector<std::uint8_t>& loop_held = out.held;
  loop_held.assign(layout.loops.size(), 0);
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
  constexpr int far = far_from_free;
  std::vector<std::uint8_t>& to_free = out.to_free;
  to_free.assign(layout.loops.size(), far);
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
  return out;
}

}  // namespace knitc::relax
