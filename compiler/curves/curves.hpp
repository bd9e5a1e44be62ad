// Curves: each yarn piece's data points interpolated by a cubic NURBS curve, sampled
// densely enough for its tube's surface, with a sweep frame and the yarn's length at
// every sample. Yarn paths in, curve pieces out.
#pragma once

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
CurvePiece trace(yarn_paths::Piece path, const Yarn& yarn, const Options& options);

// About how many samples trace() places along a piece, from its data points alone (0.87
// to 1.05 of the count on the library's fabrics): for refusing a fabric too large to
// mesh before any curve is fitted.
double estimate_samples(const yarn_paths::Piece& path, const Yarn& yarn, const Options& options);

}  // namespace knitc::curves
