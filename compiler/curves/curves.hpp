// Curves: each yarn piece's data points interpolated by a cubic NURBS curve, sampled
// densely enough for its tube's surface, with a sweep frame and the yarn's length at
// every sample. Yarn paths in, curve pieces out.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "nurbs/nurbs.hpp"
#include "pattern.hpp"
#include "sweep/sweep.hpp"
#include "yarn_paths/yarn_paths.hpp"

namespace knitc::curves {

// One yarn piece through the stage: its data points, its curve, its samples.
struct CurvePiece {
  yarn_paths::Piece path;
  nurbs::Interpolant curve;
  std::vector<double> samples;  // curve parameters, increasing
  sweep::Frames frames;         // one per sample; frames.origin are the centreline samples
  std::vector<double> arc_length;  // the yarn's length in mm from the piece's start, per sample
  // Per sample, when path.pressed is given (else empty): its pressing, interpolated
  // linearly in the curve's parameter between the data points'.
  std::vector<glm::dvec3> pressed;
  // Loop j of the piece owns samples [loop_samples[j].first, loop_samples[j].second]
  // (both ends: loops that meet share their join sample). Size: path.loops.size().
  std::vector<std::pair<std::size_t, std::size_t>> loop_samples;
};

struct Options {
  nurbs::Parametrisation parametrisation = nurbs::Parametrisation::chord_length;
  sweep::FrameKind frames = sweep::FrameKind::rotation_minimising;
  double chord_tolerance = 0.01;  // of the tube's surface, as a fraction of the yarn diameter, > 0
  // A long piece's spans are sampled, framed and measured on up to this many threads (0:
  // every core): the same samples for any count.
  int threads = 1;
};

// The frames each loop model sweeps with: Frenet for the paper's, rotation-minimising
// for the smooth one.
sweep::FrameKind frame_kind(yarn_paths::LoopModel model);

// The longest step between samples along a yarn: unbounded, but for a twisted plied
// yarn, whose plies' helices need samples where the centreline is straight.
double max_sample_step(const Yarn& yarn);

// Fits and samples one piece of `yarn`: every loop join is a sample and each loop owns
// its samples; floats, turns and tails are spans of their own.
// `same_as`, empty or one per data point: the index of an earlier point of this piece
// whose surroundings along the yarn are this one's moved by one translation (the
// relaxation's copies of its repeat, relax::Relaxed::same_as), or the point's own. A span
// between loop ends whose points, and `copy_margin` more on either side, are such copies
// of one earlier span, point for point, takes that span's samples and step lengths (its
// parameters moved along): the curve there is the earlier span's moved, to the global
// fit's reach (a cubic interpolant's influence decays by 2 - sqrt 3 a point).
inline constexpr std::size_t copy_margin = 12;
CurvePiece trace(yarn_paths::Piece path, const Yarn& yarn, const Options& options, std::span<const std::uint32_t> same_as = {});

// Per span between consecutive `breaks` (ascending indices of `points`, the first 0), the
// index of the earlier span trace() copies it from, or its own: same_as proposes the
// earlier span, which must have the same length and be sampled itself, and the points
// round both, copy_margin either side, must lie one translation apart to 1e-9 mm.
// threads >= 1 (0: every core); the same for any count.
std::vector<std::size_t> copied_spans(std::span<const std::size_t> breaks, std::span<const std::uint32_t> same_as,
                                      std::span<const glm::dvec3> points, int threads = 1);

// About how many samples trace() places along a piece, from its data points alone (0.87
// to 1.05 of the count on the library's fabrics): for refusing a fabric too large to
// mesh before any curve is fitted.
double estimate_samples(const yarn_paths::Piece& path, const Yarn& yarn, const Options& options);

}  // namespace knitc::curves
