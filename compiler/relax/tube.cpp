// A tube's chains unrolled into its layout's flat frame (tube.hpp).
#include "relax/tube.hpp"

#include <cstddef>

#include <glm/geometric.hpp>

#include "relax/relax.hpp"

namespace knitc::relax {

Unrolled unroll(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& chains) {
  Unrolled out;
  out.pieces = chains;
  out.circumference.resize(chains.size());
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const yarn_paths::Piece& piece = chains[i];
    auto& points = out.pieces[i].data_points;
    auto& circumference = out.circumference[i];
    circumference.assign(points.size(), 0.0);
    if (piece.loops.empty()) continue;  // no loop to say which course: left as traced (no tile takes it)
    auto loop_at = [&](std::size_t j) { return layout.loops[static_cast<std::size_t>(piece.loops[j])]; };
    std::size_t j = 0;  // the loop at or after point k
    for (std::size_t k = 0; k < points.size(); ++k) {
      while (j < piece.loops.size() && piece.loop_last[j] < k) ++j;
      std::size_t near = j;
      if (j == piece.loops.size()) near = j - 1;
      else if (k < piece.loop_first[j] && j > 0 && k - piece.loop_last[j - 1] <= piece.loop_first[j] - k) near = j - 1;
      const layout::Loop& loop = loop_at(near);
      double middle = 0.0;
      for (const auto& p : loop.data_points) middle += p.x;
      middle /= static_cast<double>(loop.data_points.size());
      const double c = layout::course_width(layout, loop.course);
      circumference[k] = c;
      if (c > 0.0) points[k] = layout::unroll(points[k], c, layout.course_spacing, middle);
    }
  }
  return out;
}

TubeAsFlat tube_as_flat(const layout::Layout& layout, const std::vector<yarn_paths::Piece>& laid,
                        const std::vector<yarn_paths::Piece>& relaxed) {
  const Unrolled before = unroll(layout, laid), after = unroll(layout, relaxed);
  TubeAsFlat out;
  // Unrolling keeps a segment's length but for the curvature (a few percent): one twice as
  // long or more joins points unrolled a round apart (a round's last loop and the next
  // round's first), or a point left as traced (on no loop) to one unrolled.
  auto jumps = [](const std::vector<glm::dvec3>& unrolled, const std::vector<glm::dvec3>& rolled, std::size_t k) {
    return glm::distance(unrolled[k], unrolled[k - 1]) > 2.0 * glm::distance(rolled[k], rolled[k - 1]) + 1e-9;
  };
  for (std::size_t i = 0; i < laid.size(); ++i) {
    const auto &a = before.pieces[i].data_points, &b = after.pieces[i].data_points;
    std::size_t from = 0;
    for (std::size_t k = 0; k <= a.size(); ++k) {
      // Where either list jumps: both are cut at the same points.
      const bool cut = k == a.size() || (k > from && (jumps(a, laid[i].data_points, k) || jumps(b, relaxed[i].data_points, k)));
      if (!cut) continue;
      yarn_paths::Piece x, y;
      x.yarn = y.yarn = laid[i].yarn;
      x.data_points.assign(a.begin() + static_cast<std::ptrdiff_t>(from), a.begin() + static_cast<std::ptrdiff_t>(k));
      y.data_points.assign(b.begin() + static_cast<std::ptrdiff_t>(from), b.begin() + static_cast<std::ptrdiff_t>(k));
      out.laid.push_back(std::move(x));
      out.relaxed.push_back(std::move(y));
      from = k;
    }
  }
  return out;
}

}  // namespace knitc::relax
