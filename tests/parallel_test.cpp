// The parallel loops on their kept pool of threads: every index once, a loop inside a
// loop, exceptions, and two callers at once.
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "parallel.hpp"

namespace knitc {
namespace {

TEST(Parallel, EveryIndexRunsOnceOverManyCalls) {
  // The relaxation calls a loop thousands of times: a pool that lost or doubled a block
  // between calls shows here.
  std::vector<int> hits(1000, 0);
  for (int call = 0; call < 2000; ++call)
    parallel_for(hits.size(), 4, [&](std::size_t i) { ++hits[i]; });
  for (int h : hits) ASSERT_EQ(h, 2000);
}

TEST(Parallel, ALoopInsideALoopRunsEveryIndex) {
  std::vector<std::atomic<int>> hits(64 * 64);
  parallel_for(64, 4, [&](std::size_t i) {
    parallel_for(64, 4, [&](std::size_t j) { hits[i * 64 + j].fetch_add(1); });
  });
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
}

TEST(Parallel, TheLowestBlocksExceptionComesBackAndThePoolStillWorks) {
  try {
    parallel_for(100, 4, [&](std::size_t i) {
      if (i == 10) throw std::runtime_error("ten");
      if (i == 90) throw std::runtime_error("ninety");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "ten");
  }
  std::atomic<int> sum{0};
  parallel_for(100, 4, [&](std::size_t i) { sum += static_cast<int>(i); });
  EXPECT_EQ(sum.load(), 4950);
}

TEST(Parallel, TwoCallersAtOnceBothFinish) {
  // One has the pool, the other runs on its own thread: both see every index.
  std::vector<long> totals(2, 0);
  std::vector<std::thread> callers;
  for (int k = 0; k < 2; ++k)
    callers.emplace_back([&, k] {
      for (int call = 0; call < 300; ++call) {
        std::vector<long> part(8, 0);
        parallel_for(8, 3, [&](std::size_t i) {
          for (long v = 0; v < 1000; ++v) part[i] += v;
        });
        for (long p : part) totals[static_cast<std::size_t>(k)] += p;
      }
    });
  for (auto& c : callers) c.join();
  EXPECT_EQ(totals[0], 300L * 8 * 499500);
  EXPECT_EQ(totals[1], 300L * 8 * 499500);
}

}  // namespace
}  // namespace knitc
