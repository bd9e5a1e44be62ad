#include "curves/curves.hpp"

#include <algorithm>
#include <limits>

#include "parallel.hpp"

namespace knitc::curves {

sweep::FrameKind frame_kind(yarn_paths::LoopModel model) {
  return model == yarn_paths::LoopModel::paper ? sweep::FrameKind::frenet : sweep::FrameKind::rotation_minimising;
}

double max_sample_step(const Yarn& yarn) {
  // A twelfth of a turn of the twist.
  return yarn.section == Section::plied && yarn.twist > 0.0 ? (100.0 / yarn.twist) / 12.0
                                                            : std::numeric_limits<double>::infinity();
}

CurvePiece trace(yarn_paths::Piece path, const Yarn& yarn, const Options& options) {
  CurvePiece piece;
  piece.path = std::move(path);
  nurbs::InterpolationOptions io;
  io.parametrisation = options.parametrisation;
  piece.curve = nurbs::interpolate(piece.path.data_points, io);

  // Sample span by span between the loops' ends.
  const double d = yarn.diameter;
  const double tolerance = options.chord_tolerance * d;
  const double max_step = max_sample_step(yarn);
  const auto& u = piece.curve.parameters;
  const std::size_t last = u.size() - 1;
  std::vector<std::size_t> breaks = {0, last};
  breaks.insert(breaks.end(), piece.path.loop_first.begin(), piece.path.loop_first.end());
  breaks.insert(breaks.end(), piece.path.loop_last.begin(), piece.path.loop_last.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<std::size_t> sample_at(u.size(), 0);  // the sample at each break
  // The spans between breaks are sampled independently, in parallel, then joined in order.
  const int threads = thread_count(options.threads);
  std::vector<std::vector<double>> spans(breaks.size() - 1);
  parallel_for(spans.size(), threads, [&](std::size_t k) {
    spans[k] = sweep::sample_parameters(piece.curve.curve, u[breaks[k]], u[breaks[k + 1]], tolerance, 0.5 * d, max_step);
  });
  piece.samples.push_back(u[0]);
  for (std::size_t k = 0; k < spans.size(); ++k) {
    piece.samples.insert(piece.samples.end(), spans[k].begin() + 1, spans[k].end());
    sample_at[breaks[k + 1]] = piece.samples.size() - 1;
  }
  spans = {};
  for (std::size_t j = 0; j < piece.path.loops.size(); ++j)
    piece.loop_samples.emplace_back(sample_at[piece.path.loop_first[j]], sample_at[piece.path.loop_last[j]]);
  piece.frames = sweep::frames(piece.curve.curve, piece.samples, options.frames, threads);
  // Each step's length in parallel (blocks of steps, each walking its knot spans), then
  // summed in order.
  std::vector<double> step(piece.samples.size(), 0.0);
  constexpr std::size_t block = 1024;
  const std::size_t steps = piece.samples.size() - 1;
  parallel_for((steps + block - 1) / block, threads, [&](std::size_t b) {
    const std::size_t from = b * block, to = std::min(steps, from + block);
    nurbs::segment_lengths(piece.curve.curve, std::span<const double>(piece.samples).subspan(from, to - from + 1),
                           std::span<double>(step).subspan(from + 1, to - from));
  });
  piece.arc_length.assign(piece.samples.size(), 0.0);
  for (std::size_t i = 1; i < piece.samples.size(); ++i) piece.arc_length[i] = piece.arc_length[i - 1] + step[i];
  if (piece.path.pressed.size() == u.size()) {
    const auto& at = piece.path.pressed;
    piece.pressed.resize(piece.samples.size());
    std::size_t k = 0;  // the data points' span [u[k], u[k + 1]] holding the sample
    for (std::size_t i = 0; i < piece.samples.size(); ++i) {
      const double x = piece.samples[i];
      while (k + 2 < u.size() && u[k + 1] <= x) ++k;
      const double span = u[k + 1] - u[k];
      const double t = span > 0.0 ? std::clamp((x - u[k]) / span, 0.0, 1.0) : 0.0;
      piece.pressed[i] = (1.0 - t) * at[k] + t * at[k + 1];
    }
  }
  return piece;
}

double estimate_samples(const yarn_paths::Piece& path, const Yarn& yarn, const Options& options) {
  return sweep::estimate_samples(path.data_points, options.chord_tolerance * yarn.diameter, 0.5 * yarn.diameter,
                                 max_sample_step(yarn));
}

}  // namespace knitc::curves
