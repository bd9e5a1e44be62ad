#include "curves/curves.hpp"

#include <algorithm>
#include <cassert>
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

std::vector<std::size_t> copied_spans(std::span<const std::size_t> breaks, std::span<const std::uint32_t> same_as,
                                      std::span<const glm::dvec3> points, int threads) {
  constexpr double same = 1e-9;  // mm
  const std::size_t spans = breaks.size() - 1;
  std::vector<std::size_t> from(spans);
  for (std::size_t k = 0; k < spans; ++k) from[k] = k;
  if (same_as.empty()) return from;
  // Which earlier span each span's points repeat, in parallel (spans for none); then, in
  // order, taken where that span is sampled itself.
  std::vector<std::size_t> proposed(spans, spans);
  parallel_for(spans, thread_count(threads), [&](std::size_t k) {
    const std::size_t a = breaks[k], b = breaks[k + 1];
    if (same_as[a] >= a || b + copy_margin >= points.size()) return;
    const std::size_t shift = a - same_as[a];
    if (a - shift < copy_margin) return;
    // The span starting at the break a - shift, if one does.
    const auto at = std::lower_bound(breaks.begin(), breaks.end() - 1, a - shift);
    if (at == breaks.end() - 1 || *at != a - shift) return;
    const auto r = static_cast<std::size_t>(at - breaks.begin());
    if (breaks[r + 1] != b - shift) return;
    const glm::dvec3 move = points[a] - points[a - shift];
    for (std::size_t i = a - copy_margin; i <= b + copy_margin; ++i) {
      const glm::dvec3 off = points[i] - points[i - shift] - move;
      if (std::abs(off.x) > same || std::abs(off.y) > same || std::abs(off.z) > same) return;
    }
    proposed[k] = r;
  });
  for (std::size_t k = 0; k < spans; ++k)
    if (proposed[k] != spans && from[proposed[k]] == proposed[k]) from[k] = proposed[k];
  return from;
}

CurvePiece trace(yarn_paths::Piece path, const Yarn& yarn, const Options& options, std::span<const std::uint32_t> same_as) {
  CurvePiece piece;
  piece.path = std::move(path);
  assert(same_as.empty() || same_as.size() == piece.path.data_points.size());
  nurbs::InterpolationOptions io;
  io.parametrisation = options.parametrisation;
  io.threads = options.threads;
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
  std::vector<std::size_t> sample_at(breaks.size(), 0);  // the sample at each break
  // The spans between breaks are sampled and their steps measured independently, in
  // parallel, then joined in order; a copy takes its span's, moved along.
  const int threads = thread_count(options.threads);
  const std::vector<std::size_t> from = copied_spans(breaks, same_as, piece.path.data_points, threads);
  std::vector<std::vector<double>> spans(breaks.size() - 1), steps(spans.size());
  auto sample = [&](std::size_t k) {
    spans[k] = sweep::sample_parameters(piece.curve.curve, u[breaks[k]], u[breaks[k + 1]], tolerance, 0.5 * d, max_step);
    steps[k].resize(spans[k].size() - 1);
    nurbs::segment_lengths(piece.curve.curve, spans[k], steps[k]);
  };
  parallel_for(spans.size(), threads, [&](std::size_t k) {
    if (from[k] == k) sample(k);
  });
  parallel_for(spans.size(), threads, [&](std::size_t k) {
    const std::size_t r = from[k];
    if (r == k) return;
    const double a = u[breaks[k]], b = u[breaks[k + 1]], shift = a - u[breaks[r]];
    spans[k] = spans[r];
    for (double& s : spans[k]) s += shift;
    spans[k].front() = a;
    spans[k].back() = b;
    // The moved parameters still ascend inside [a, b] (else the span is sampled afresh).
    bool ascending = true;
    for (std::size_t i = 1; i < spans[k].size(); ++i) ascending = ascending && spans[k][i - 1] < spans[k][i];
    if (ascending) steps[k] = steps[r];
    else sample(k);
  });
  std::size_t samples = 1;
  for (const auto& span : spans) samples += span.size() - 1;
  piece.samples.reserve(samples);
  piece.arc_length.reserve(samples);
  piece.samples.push_back(u[0]);
  piece.arc_length.push_back(0.0);
  for (std::size_t k = 0; k < spans.size(); ++k) {
    piece.samples.insert(piece.samples.end(), spans[k].begin() + 1, spans[k].end());
    for (const double step : steps[k]) piece.arc_length.push_back(piece.arc_length.back() + step);
    sample_at[k + 1] = piece.samples.size() - 1;
  }
  spans = {};
  steps = {};
  // A loop's ends are breaks: found among them.
  auto sample_of = [&](std::size_t point) {
    return sample_at[static_cast<std::size_t>(std::lower_bound(breaks.begin(), breaks.end(), point) - breaks.begin())];
  };
  for (std::size_t j = 0; j < piece.path.loops.size(); ++j)
    piece.loop_samples.emplace_back(sample_of(piece.path.loop_first[j]), sample_of(piece.path.loop_last[j]));
  piece.frames = sweep::frames(piece.curve.curve, piece.samples, options.frames, threads);
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
