#include "relax/tiled_start.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "parallel.hpp"
#include "relax/contacts.hpp"
#include "relax/repeat.hpp"
#include "spatial/columns.hpp"

namespace knitc::relax {

AlongYarn along_yarn(const std::vector<yarn_paths::Piece>& chains, const std::vector<yarn::Size>& sizes) {
  AlongYarn y;
  std::size_t n = 0;
  for (const auto& piece : chains) n += piece.data_points.size();
  y.along.reserve(n);
  y.piece.reserve(n);
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const yarn::Size& size = sizes[static_cast<std::size_t>(chains[i].yarn)];
    y.thickest = std::max(y.thickest, size.free_diameter);
    y.piece_core.push_back(0.5 * size.core_diameter);
    double s = 0.0;
    for (std::size_t k = 0; k < chains[i].data_points.size(); ++k) {
      if (k > 0) s += glm::distance(chains[i].data_points[k - 1], chains[i].data_points[k]);
      y.along.push_back(s);
      y.piece.push_back(static_cast<std::uint32_t>(i));
    }
  }
  return y;
}

void free_where_held_overlap(const AlongYarn& yarn, Start& start, const std::vector<std::uint8_t>& look_from,
                             const std::vector<std::uint8_t>& look_at, int threads) {
  assert(yarn.along.size() == start.pos.size());
  const std::vector<double>& along = yarn.along;
  const std::vector<std::uint32_t>& piece = yarn.piece;
  const std::vector<double>& piece_core = yarn.piece_core;
  const double thickest = yarn.thickest;
  auto core = [&](std::size_t i) { return piece_core[piece[i]]; };
  if (thickest <= 0.0) return;
  spatial::Columns grid(thickest);
  for (std::size_t i = 0; i < start.pos.size(); ++i)
    if (start.held[i] && look_at[i]) grid.add(grid.cell_of(start.pos[i]), static_cast<std::uint32_t>(i));
  grid.index();
  const std::size_t n = start.pos.size(), block = 4096, blocks = (n + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> overlapping(blocks);
  parallel_for(blocks, thread_count(threads), [&](std::size_t b) {
    for (std::size_t i = b * block; i < std::min(n, (b + 1) * block); ++i) {
      if (!start.held[i] || !look_from[i]) continue;
      grid.near(grid.cell_of(start.pos[i]), [&](const spatial::Columns::Entry& e) {
        const std::size_t j = e.item;
        if (j <= i) return;
        if (piece[i] == piece[j] && std::abs(along[i] - along[j]) <= 2.0 * thickest) return;  // one stretch of yarn
        if (glm::distance(start.pos[i], start.pos[j]) < core(i) + core(j)) {
          overlapping[b].push_back(static_cast<std::uint32_t>(i));
          overlapping[b].push_back(static_cast<std::uint32_t>(j));
        }
      });
    }
  });
  constexpr std::size_t reach = 48;  // points either way: about a loop
  for (const auto& list : overlapping)
    for (const std::uint32_t i : list) {
      const std::size_t from = i >= reach ? i - reach : 0, to = std::min(n, static_cast<std::size_t>(i) + reach + 1);
      for (std::size_t k = from; k < to; ++k)
        if (piece[k] == piece[i]) start.held[k] = 0;
    }
}

// Per point: 1 free, 2 held within `reach` (mm) of a free one, 0 neither.
std::vector<std::uint8_t> near_free(const Start& start, double reach, int threads) {
  std::vector<std::uint8_t> needed(start.pos.size(), 0);
  spatial::Columns grid(reach);
  for (std::size_t g = 0; g < start.pos.size(); ++g)
    if (!start.held[g]) {
      needed[g] = 1;
      grid.add(grid.cell_of(start.pos[g]), static_cast<std::uint32_t>(g));
    }
  grid.index();
  // Only points in a column beside a free one's can be within reach (the cell's width).
  const spatial::ColumnMask beside_free(start.pos, grid, [&](std::size_t g) { return !start.held[g]; });
  // Each point answers for itself: blocks of points in parallel.
  const std::size_t n = start.pos.size(), block = 4096;
  parallel_for((n + block - 1) / block, thread_count(threads), [&](std::size_t b) {
    for (std::size_t g = b * block; g < std::min(n, (b + 1) * block); ++g) {
      if (needed[g]) continue;
      const glm::i64vec3 cell = grid.cell_of(start.pos[g]);
      if (!beside_free.holds(cell)) continue;
      grid.near(cell, [&](const spatial::Columns::Entry& e) {
        if (!needed[g] && glm::distance(start.pos[e.item], start.pos[g]) <= reach) needed[g] = 2;
      });
    }
  });
  return needed;
}

// `needed`: near_free's.
Crop crop(const std::vector<yarn_paths::Piece>& chains, const Start& start, std::vector<std::uint8_t> needed) {
  std::vector<std::size_t> first(chains.size() + 1, 0);
  for (std::size_t i = 0; i < chains.size(); ++i) first[i + 1] = first[i] + chains[i].data_points.size();
  Crop out;
  constexpr std::size_t stencil = 4;  // points either way along the yarn
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const auto& piece = chains[i];
    const std::size_t n = piece.data_points.size();
    std::vector<std::uint8_t> keep(n, 0);
    for (std::size_t k = 0; k < n; ++k)
      if (needed[first[i] + k])
        for (std::size_t u = k >= stencil ? k - stencil : 0; u < std::min(n, k + stencil + 1); ++u) keep[u] = 1;
    // Whole loops, judged on the points above (loops that meet share a point: judged on
    // the filled ones, one loop would pull in the next, and so the whole piece).
    const std::vector<std::uint8_t> touched = keep;
    for (std::size_t j = 0; j < piece.loops.size(); ++j) {
      bool any = false;
      for (std::size_t k = piece.loop_first[j]; k <= piece.loop_last[j] && !any; ++k) any = touched[k] != 0;
      if (any) std::fill(keep.begin() + static_cast<std::ptrdiff_t>(piece.loop_first[j]),
                         keep.begin() + static_cast<std::ptrdiff_t>(piece.loop_last[j] + 1), std::uint8_t{1});
    }
    std::size_t k = 0, j = 0;
    while (k < n) {
      if (!keep[k]) {
        ++k;
        continue;
      }
      std::size_t end = k;
      while (end < n && keep[end]) ++end;
      if (end - k >= 2) {
        yarn_paths::Piece run;
        run.yarn = piece.yarn;
        run.data_points.assign(piece.data_points.begin() + static_cast<std::ptrdiff_t>(k),
                               piece.data_points.begin() + static_cast<std::ptrdiff_t>(end));
        while (j < piece.loops.size() && piece.loop_last[j] < k) ++j;
        for (std::size_t l = j; l < piece.loops.size() && piece.loop_first[l] < end; ++l) {
          if (piece.loop_first[l] < k || piece.loop_last[l] >= end) continue;
          run.loops.push_back(piece.loops[l]);
          run.loop_first.push_back(piece.loop_first[l] - k);
          run.loop_last.push_back(piece.loop_last[l] - k);
        }
        out.start.pos.insert(out.start.pos.end(), start.pos.begin() + static_cast<std::ptrdiff_t>(first[i] + k),
                             start.pos.begin() + static_cast<std::ptrdiff_t>(first[i] + end));
        out.start.held.insert(out.start.held.end(), start.held.begin() + static_cast<std::ptrdiff_t>(first[i] + k),
                              start.held.begin() + static_cast<std::ptrdiff_t>(first[i] + end));
        out.pieces.push_back(std::move(run));
        out.origin.emplace_back(i, k);
      }
      k = end;
    }
  }
  out.needed = std::move(needed);
  return out;
}

bool deeper_than_laid(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& laid, const std::vector<yarn::Size>& sizes,
                      const Start& start, int threads) {
  Chains c = chains_of(layout, laid, sizes, Boundary::free);
  assert(start.pos.size() == c.pos.size() && start.held.size() == c.pos.size());
  Contacts contacts(glm::dvec2(0.0), contact_margin * c.thickest, false, thread_count(threads));
  contacts.find(c);
  const double deepest_laid = contacts.deepest(c);
  c.pos = start.pos;
  for (std::size_t i = 0; i < c.pos.size(); ++i)
    if (start.held[i]) c.inv_mass[i] = 0.0;
  contacts.find(c);
  return contacts.deepest(c) > deepest_laid + deeper_by_tiling * c.thickest_core;
}

}  // namespace knitc::relax
