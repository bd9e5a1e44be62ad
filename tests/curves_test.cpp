// The curves stage's copies (compiler/curves): a span of a piece that repeats an earlier
// one, one translation away with everything round it, takes the earlier span's samples
// and step lengths; the result lies where sampling it afresh puts it.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "curves/curves.hpp"

namespace knitc {
namespace {

constexpr std::size_t period = 24;  // points of one repeat, 4 "loops" of 6 points
constexpr std::size_t repeats = 12;
const glm::dvec3 step_of_repeat(9.0, 0.5, 0.0);

// A wavy yarn repeating every `period` points, moved by step_of_repeat each time, cut into
// loops of 6 points; same_as points each repeat's point at the second repeat's (the first
// copy), but for the first and last repeats, which stand for edges: they lie otherwise.
struct Wave {
  yarn_paths::Piece path;
  std::vector<std::uint32_t> same_as;
};

Wave wave() {
  Wave w;
  for (std::size_t r = 0; r < repeats; ++r)
    for (std::size_t k = 0; k < period; ++k) {
      const double t = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(period);
      const glm::dvec3 local(9.0 * static_cast<double>(k) / static_cast<double>(period) + 1.2 * std::sin(2.0 * t),
                             1.5 * std::sin(t), 0.8 * std::cos(3.0 * t));
      const bool edge = r == 0 || r + 1 == repeats;
      w.path.data_points.push_back(local + static_cast<double>(r) * step_of_repeat + glm::dvec3(0.0, 0.0, edge ? 0.3 * std::sin(t) : 0.0));
      const std::size_t at = r * period + k;
      w.same_as.push_back(static_cast<std::uint32_t>(edge || r == 1 ? at : period + k));
    }
  for (std::size_t j = 0; j * 6 + 6 < w.path.data_points.size(); ++j) {
    w.path.loops.push_back(static_cast<int>(j));
    w.path.loop_first.push_back(j * 6);
    w.path.loop_last.push_back(j * 6 + 6);
  }
  return w;
}

std::vector<std::size_t> breaks_of(const yarn_paths::Piece& path) {
  std::vector<std::size_t> b = {0};
  for (std::size_t last : path.loop_last) b.push_back(last);
  if (b.back() + 1 < path.data_points.size()) b.push_back(path.data_points.size() - 1);
  return b;
}

TEST(CurveCopies, ASpanIsCopiedWhereItAndItsFirstCopyLieAmongCopiesToTheMargin) {
  const Wave w = wave();
  const auto breaks = breaks_of(w.path);
  const auto from = curves::copied_spans(breaks, w.same_as, w.path.data_points);
  // The interior repeats are [period, (repeats - 1) period): a span is copied where it
  // lies past the second repeat and the points round it and round its first copy, to the
  // margin either way, are all interior.
  const std::size_t m = curves::copy_margin, inner_end = (repeats - 1) * period;
  std::size_t copied = 0;
  for (std::size_t k = 0; k < from.size(); ++k) {
    const std::size_t a = breaks[k], b = breaks[k + 1];
    const std::size_t first = period + a % period;
    const bool expected = a >= 2 * period && a < inner_end && a >= m && b + m < inner_end && first >= period + m &&
                          first + (b - a) + m < inner_end;
    EXPECT_EQ(from[k] != k, expected) << "span " << k << " [" << a << ", " << b << "]";
    if (from[k] == k) continue;
    ++copied;
    EXPECT_EQ(breaks[from[k]], first);
    EXPECT_EQ(breaks[from[k] + 1], first + (b - a));
  }
  EXPECT_GE(copied, 10u);
  // Found on two threads: the same.
  EXPECT_EQ(curves::copied_spans(breaks, w.same_as, w.path.data_points, 2), from);
}

TEST(CurveCopies, APointOutOfPlaceNearASpanStopsItsCopy) {
  Wave w = wave();
  const auto breaks = breaks_of(w.path);
  const std::size_t moved = 6 * period + 3;  // inside a span of the seventh repeat
  w.path.data_points[moved] += glm::dvec3(0.0, 0.0, 1e-6);
  const auto from = curves::copied_spans(breaks, w.same_as, w.path.data_points);
  for (std::size_t k = 0; k < from.size(); ++k) {
    const bool near = breaks[k] <= moved + curves::copy_margin && breaks[k + 1] + curves::copy_margin >= moved;
    if (near) {
      EXPECT_EQ(from[k], k) << "span " << k;
    }
  }
  // Others still copy.
  std::size_t copied = 0;
  for (std::size_t k = 0; k < from.size(); ++k) copied += from[k] != k ? 1 : 0;
  EXPECT_GE(copied, 6u);
}

TEST(CurveCopies, ACopiedPieceLiesWhereSamplingItAfreshPutsIt) {
  const Wave w = wave();
  Yarn yarn;
  yarn.diameter = 1.0;
  curves::Options options;
  options.chord_tolerance = 0.01;
  const curves::CurvePiece fresh = curves::trace(w.path, yarn, options);
  const curves::CurvePiece copied = curves::trace(w.path, yarn, options, w.same_as);
  ASSERT_EQ(copied.samples.size(), fresh.samples.size());
  ASSERT_EQ(copied.loop_samples, fresh.loop_samples);
  double worst = 0.0, worst_length = 0.0;
  for (std::size_t i = 0; i < fresh.samples.size(); ++i) {
    worst = std::max(worst, glm::distance(copied.frames.origin[i], fresh.frames.origin[i]));
    worst_length = std::max(worst_length, std::abs(copied.arc_length[i] - fresh.arc_length[i]));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_length, 1e-6);
}

}  // namespace
}  // namespace knitc
