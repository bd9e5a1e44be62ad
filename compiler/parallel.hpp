// Deterministic parallel loops: the work is cut into contiguous blocks by index, each
// result lands in its own slot, so the output never depends on the thread count.
//
// The blocks run on a pool of threads started once and kept (parallel.cpp): the
// relaxation calls a parallel loop four times a sweep, hundreds of sweeps, and a thread
// started for each call cost more than the work it shared on a small fabric.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace knitc {

// The number of threads to use for `requested` (0: every core the machine has).
inline int thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace parallel {
// Calls block(b) for every b in [0, blocks), each once, on the pool's threads and the
// caller's; returns when all have returned. block must not throw. A call from inside a
// block, or while another caller has the pool, runs its blocks on the calling thread, in
// order.
void run_blocks(std::size_t blocks, const std::function<void(std::size_t)>& block);
}  // namespace parallel

// Calls body(i) for i in [0, count), on up to `threads` threads. Rethrows the first
// exception of the lowest block that threw.
template <class Body>
void parallel_for(std::size_t count, int threads, Body&& body) {
  const std::size_t blocks = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count);
  if (blocks <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::vector<std::exception_ptr> errors(blocks);
  parallel::run_blocks(blocks, [&](std::size_t b) {
    try {
      const std::size_t first = count * b / blocks, last = count * (b + 1) / blocks;
      for (std::size_t i = first; i < last; ++i) body(i);
    } catch (...) {
      errors[b] = std::current_exception();
    }
  });
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace knitc
