// A tube's chains unrolled into its layout's flat frame (tube.hpp).
#include "relax/tube.hpp"

#include <cstddef>

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

}  // namespace knitc::relax
