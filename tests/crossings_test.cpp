// The knot diagram seen from the face (measure/crossings): which yarn crosses in front
// where, and what a relaxation changed of it: kept, flipped, lost and new crossings, a
// pair slid in beside a crossing, an end drawn back, and only the segments asked about
// counted. Its use on relaxed fabrics: tests/relax_test.cpp.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "measure/crossings.hpp"

namespace knitc {
namespace {

TEST(Crossings, OnlyTheCountedAreCountedButAllMatch) {
  yarn_paths::Piece across, up, other;
  across.data_points = {{-1, 0, 0}, {1, 0, 0}};
  up.data_points = {{0, -1, 0.5}, {0, 1, 0.5}};
  other.data_points = {{0.5, -1, 0.5}, {0.5, 1, 0.5}};
  const auto x = measure::crossings({across, up, other});
  ASSERT_EQ(x.size(), 2u);
  // Both gone: only the counted one is lost.
  up.data_points = {{3, -1, 0.5}, {3, 1, 0.5}};
  other.data_points = {{3.5, -1, 0.5}, {3.5, 1, 0.5}};
  const auto y = measure::crossings({across, up, other});
  EXPECT_EQ(measure::compare(x, y, 2, 0, 0.0, {}, {1, 0}, {}).lost, 1u);
  EXPECT_EQ(measure::compare(x, y, 2).lost, 2u);
  // Kept where either side of a match counts.
  EXPECT_EQ(measure::compare(x, x, 2, 0, 0.0, {}, {0, 1}, {0, 0}).kept, 1u);
  EXPECT_EQ(measure::compare(x, x, 2, 0, 0.0, {}, {0, 0}, {1, 0}).kept, 1u);
}

TEST(Crossings, CountsOverAndUnderAndSeesAFlip) {
  yarn_paths::Piece across, up;
  across.data_points = {{-1, 0, 0}, {1, 0, 0}};
  up.data_points = {{0, -1, 0.5}, {0, 1, 0.5}};
  const auto x = measure::crossings({across, up});
  ASSERT_EQ(x.size(), 1u);
  EXPECT_EQ(x[0].piece_a, 0u);
  EXPECT_DOUBLE_EQ(x[0].depth, -0.5);  // the second piece is in front
  up.data_points = {{0, -1, -0.5}, {0, 1, -0.5}};
  const auto y = measure::crossings({across, up});
  const auto c = measure::compare(x, y, 2);
  EXPECT_EQ(c.flipped, 1u);
  EXPECT_EQ(c.kept, 0u);
  up.data_points = {{3, -1, 0.5}, {3, 1, 0.5}};  // moved aside: the crossing is gone
  const auto lost = measure::compare(x, measure::crossings({across, up}), 2);
  EXPECT_EQ(lost.lost, 1u);
}

// Two yarns laid through one point, each bending there (as a twisted stitch's legs are
// laid), cross once, however the point's coordinates round.
TEST(Crossings, AThroughPointCountsOnce) {
  int wrong = 0;
  for (int k = 1; k <= 500; ++k) {
    const glm::dvec3 p(0.0137 * k, 0.0071 * k, 0.0);
    yarn_paths::Piece a, b;
    a.data_points = {p + glm::dvec3(-1.1, -0.3, 0.5), p + glm::dvec3(0, 0, 0.5), p + glm::dvec3(0.9, 0.4, 0.5)};
    b.data_points = {p + glm::dvec3(-0.3, 1.1, 0), p, p + glm::dvec3(0.4, -0.9, 0)};
    wrong += measure::crossings({a, b}).size() == 1u ? 0 : 1;
  }
  EXPECT_EQ(wrong, 0);
}

// A pair of crossings slid in beside a crossing of the same two yarns, the other one in
// front at both (Reidemeister's second move), is not the crossing flipped: the crossing
// slid along and is kept, and the pair is new, together.
TEST(Crossings, APairSlidInBesideACrossingIsNoFlip) {
  yarn_paths::Piece across, wave;
  for (int i = 0; i <= 20; ++i) across.data_points.push_back({i * 0.5, 0.0, 0.0});
  wave.data_points = {{1.0, -1.0, 0.5}, {1.4, 1.0, 0.5}, {4.0, 1.0, 0.5}};  // in front, near x = 1.2
  const auto before = measure::crossings({across, wave});
  ASSERT_EQ(before.size(), 1u);
  // Behind at x = 1.1 and 1.6 (the pair), then in front at x = 2.6 (the crossing, slid).
  wave.data_points = {{1.1, -1.0, -0.5}, {1.1, 1.0, -0.5}, {1.6, 1.0, -0.5}, {1.6, -1.0, -0.5}, {2.0, -1.0, 0.5}, {3.2, 1.0, 0.5}};
  const auto after = measure::crossings({across, wave});
  ASSERT_EQ(after.size(), 3u);
  const auto c = measure::compare(before, after, 12);
  EXPECT_EQ(c.flipped, 0u);
  EXPECT_EQ(c.kept, 1u);
  EXPECT_EQ(c.found, 2u);
  EXPECT_EQ(c.found_alone, 0u);
  // Flipped for real, the crossing still shows.
  wave.data_points = {{1.0, -1.0, -0.5}, {1.4, 1.0, -0.5}, {4.0, 1.0, -0.5}};
  EXPECT_EQ(measure::compare(before, measure::crossings({across, wave}), 12).flipped, 1u);
}

// A yarn's free end drawn back past another yarn unmakes their crossing alone, with no
// yarn through another: told apart from a lone loss in the middle of a yarn, which the
// measure counts as a possible pass-through.
TEST(Crossings, AnEndDrawnBackIsNoPassThrough) {
  yarn_paths::Piece across, tail;
  for (int i = 0; i <= 40; ++i) across.data_points.push_back({i * 0.5 - 10.0, 0.0, 0.0});
  for (int i = 0; i <= 30; ++i) tail.data_points.push_back({0.0, i * 0.5 - 14.0, 0.2});  // ends at y = 1
  const auto before = measure::crossings({across, tail});
  ASSERT_EQ(before.size(), 1u);
  for (auto& p : tail.data_points) p.y -= 2.0;  // drawn back: its end now short of the other yarn
  const auto after = measure::crossings({across, tail});
  ASSERT_EQ(after.size(), 0u);
  const std::vector<std::uint32_t> segments = {40, 30};
  const auto blind = measure::compare(before, after, 12, 24, 1.0);
  EXPECT_EQ(blind.lost_alone_touching, 1u);  // with no lengths given, it could be a pass-through
  const auto seen = measure::compare(before, after, 12, 24, 1.0, segments);
  EXPECT_EQ(seen.lost_alone, 0u);
  EXPECT_EQ(seen.lost_alone_touching, 0u);
  EXPECT_EQ(seen.lost_at_end, 1u);
  EXPECT_EQ(measure::passed_through(seen), 0u);
  // A loss far from both yarns' ends still counts alone: the middle of a long yarn
  // pulled round the end of another, 50 segments away along it.
  yarn_paths::Piece long_across, long_up;
  for (int i = 0; i <= 100; ++i) long_across.data_points.push_back({i * 0.5 - 25.0, 0.0, 0.0});
  for (int i = 0; i <= 300; ++i) long_up.data_points.push_back({0.0, i * 0.5 - 75.0, 0.2});
  const auto long_before = measure::crossings({long_across, long_up});
  ASSERT_EQ(long_before.size(), 1u);
  for (auto& p : long_up.data_points)
    if (p.y > -2.0 && p.y < 2.0) p.x = 30.0;
  const auto long_after = measure::crossings({long_across, long_up});
  ASSERT_EQ(long_after.size(), 0u);
  const auto middle = measure::compare(long_before, long_after, 12, 24, 1.0, {100, 300});
  EXPECT_EQ(middle.lost_at_end, 0u);
  EXPECT_EQ(middle.lost_alone_touching, 1u);
}

}  // namespace
}  // namespace knitc
