#include "relax/chains.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "nurbs/nurbs.hpp"
#include "parallel.hpp"

namespace knitc::relax {

std::vector<yarn_paths::Piece> refine(std::vector<yarn_paths::Piece> pieces, const std::vector<double>& diameter,
                                      double spacing, int threads) {
  assert(spacing > 0.0);
  for (yarn_paths::Piece& piece : pieces) {
    if (piece.data_points.size() < 2) continue;
    const double step = spacing * diameter[static_cast<std::size_t>(piece.yarn)];
    nurbs::InterpolationOptions io;
    io.threads = threads;
    const auto curve = nurbs::interpolate(piece.data_points, io);
    // Where each old point goes: after the points inserted before it.
    const std::size_t n = piece.data_points.size();
    std::vector<std::size_t> new_index(n, 0);
    for (std::size_t k = 1; k < n; ++k) {
      const auto inserted = static_cast<std::size_t>(std::ceil(glm::distance(piece.data_points[k - 1], piece.data_points[k]) / step));
      new_index[k] = new_index[k - 1] + std::max<std::size_t>(inserted, 1);
    }
    std::vector<glm::dvec3> points(new_index.back() + 1);
    // In blocks of old points, each walking its inserted points' knot spans (ascending),
    // not searching: the same points for any thread count.
    constexpr std::size_t block = 4096;
    const int last_span = static_cast<int>(curve.curve.points.size()) - 1;
    parallel_for((n + block - 1) / block, thread_count(threads), [&](std::size_t b) {
      const std::size_t from = b * block, to = std::min(n, from + block);
      int span = nurbs::find_span(curve.curve, curve.parameters[from > 0 ? from - 1 : 0]);  // the first inserted point's
      for (std::size_t k = from; k < to; ++k) {
        if (k > 0) {
          const std::size_t m = new_index[k] - new_index[k - 1];
          const double u0 = curve.parameters[k - 1], u1 = curve.parameters[k];
          for (std::size_t j = 1; j < m; ++j) {
            const double u = u0 + (u1 - u0) * static_cast<double>(j) / static_cast<double>(m);
            while (span < last_span && curve.curve.knots[static_cast<std::size_t>(span) + 1] <= u) ++span;
            points[new_index[k - 1] + j] = nurbs::derivatives(curve.curve, span, u, 0)[0];
          }
        }
        points[new_index[k]] = piece.data_points[k];
      }
    });
    for (std::size_t& first : piece.loop_first) first = new_index[first];
    for (std::size_t& last : piece.loop_last) last = new_index[last];
    piece.data_points = std::move(points);
  }
  return pieces;
}

Chains chains_of(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& pieces,
                 const std::vector<yarn::Size>& sizes, Boundary boundary) {
  Chains c;
  std::size_t total = 0;
  for (const auto& p : pieces) total += p.data_points.size();
  c.pos.reserve(total);
  c.radius.reserve(total);
  c.shell.reserve(total);
  c.along.reserve(total);
  c.inv_mass.reserve(total);
  c.piece.reserve(total);
  std::vector<std::int8_t> on_loop;  // per point: 0 off every loop, 1 on one, 2 on a held one
  on_loop.reserve(total);
  const int last_course = layout.courses - 1;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto& p = pieces[i];
    c.first.push_back(c.pos.size());
    const yarn::Size& size = sizes[static_cast<std::size_t>(p.yarn)];
    c.thickest = std::max(c.thickest, size.free_diameter);
    c.thickest_core = std::max(c.thickest_core, size.core_diameter);
    std::vector<std::int8_t> mark(p.data_points.size(), 0);
    for (std::size_t j = 0; j < p.loops.size(); ++j) {
      const auto& loop = layout.loops[static_cast<std::size_t>(p.loops[j])];
      const bool held = boundary == Boundary::held && (loop.course == 0 || loop.course == last_course);
      for (std::size_t k = p.loop_first[j]; k <= p.loop_last[j]; ++k) mark[k] = std::max<std::int8_t>(mark[k], held ? 2 : 1);
    }
    double along = 0.0;
    for (std::size_t k = 0; k < p.data_points.size(); ++k) {
      if (k > 0) along += glm::distance(p.data_points[k - 1], p.data_points[k]);
      c.pos.push_back(p.data_points[k]);
      c.radius.push_back(0.5 * size.core_diameter);
      c.shell.push_back(0.5 * size.free_diameter);
      c.along.push_back(along);
      c.inv_mass.push_back(mark[k] == 2 ? 0.0 : 1.0);
      c.piece.push_back(static_cast<std::uint32_t>(i));
      on_loop.push_back(mark[k]);
    }
  }
  c.first.push_back(c.pos.size());
  c.along_period.assign(pieces.size(), 0.0);
  c.rest = c.pos;
  c.on_loop.resize(on_loop.size());
  for (std::size_t i = 0; i < on_loop.size(); ++i) c.on_loop[i] = on_loop[i] > 0 ? 1 : 0;
  c.segment.assign(c.pos.size(), 0);
  c.contactable.assign(c.pos.size(), 0);
  c.rest_length.assign(c.pos.size(), 0.0);
  for (std::size_t i = 0; i + 1 < c.pos.size(); ++i) {
    if (c.piece[i] != c.piece[i + 1]) continue;
    c.segment[i] = 1;
    c.rest_length[i] = glm::distance(c.pos[i], c.pos[i + 1]);
    c.contactable[i] = boundary != Boundary::periodic || (on_loop[i] > 0 && on_loop[i + 1] > 0);
  }
  return c;
}

}  // namespace knitc::relax
