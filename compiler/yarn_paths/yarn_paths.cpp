#include "yarn_paths/yarn_paths.hpp"

namespace knitc::yarn_paths {

namespace {

void append_loop(Piece& piece, const layout::Layout& layout, int index) {
  const auto& points = layout.loops[index].data_points;
  // Consecutive loops share an end point: the next loop's P0 is this one's P16.
  const int first = piece.data_points.empty() ? 0 : 1;
  piece.data_points.insert(piece.data_points.end(), points.begin() + first, points.end());
  piece.loops.push_back(index);
}

}  // namespace

std::vector<Piece> trace(const layout::Layout& layout, LoopModel model) {
  std::vector<Piece> pieces;
  const int count = static_cast<int>(layout.loops.size());
  for (int i = 0; i < count; ++i) {
    const layout::Loop& loop = layout.loops[i];
    const bool starts_piece =
        model == LoopModel::paper || pieces.empty() ||
        layout.loops[i - 1].course != loop.course || layout.loops[i - 1].yarn != loop.yarn;
    if (starts_piece) {
      pieces.emplace_back();
      pieces.back().yarn = loop.yarn;
      pieces.back().data_points.reserve(model == LoopModel::paper ? layout::loop_points
                                                                  : layout.wales * points_per_loop + 1);
    }
    append_loop(pieces.back(), layout, i);
  }
  return pieces;
}

}  // namespace knitc::yarn_paths
