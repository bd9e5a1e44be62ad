#include "parallel.hpp"

#include <pthread.h>
#include <csignal>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace knitc::parallel {

namespace {

// True on a pool thread, and on a caller while it runs blocks: a parallel loop inside a
// block runs serially rather than wait for threads that are busy with its own caller.
thread_local bool in_block = false;

// Workers sleep until a job is posted (a new generation), take its blocks by an atomic
// counter, and the caller (who takes blocks too) returns once every block has run and no
// worker is still on the job, so a worker never holds a finished job. A worker reads the
// job under the lock, so one that wakes late sees the next job or none. The pool grows to
// the most blocks asked for, less the caller's thread; its threads live until the end.
class Pool {
 public:
  ~Pool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }

  // False if another caller has the pool now.
  bool run(std::size_t blocks, const std::function<void(std::size_t)>& block) {
    std::unique_lock busy(caller_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      std::lock_guard lock(mutex_);
      while (workers_.size() + 1 < blocks)
        workers_.emplace_back([this] {
          // Signals go to the threads that called in, never to a worker: a caller that
          // holds them off (the writers, while a temporary is made and registered) must
          // not have a worker take one meanwhile.
          sigset_t all;
          sigfillset(&all);
          ::pthread_sigmask(SIG_BLOCK, &all, nullptr);
          work();
        });
      job_ = &block;
      blocks_ = blocks;
      next_.store(0);
      left_ = blocks;
      ++generation_;
    }
    wake_.notify_all();
    const std::size_t finished = take_blocks(block, blocks);
    std::unique_lock lock(mutex_);
    left_ -= finished;
    done_.wait(lock, [&] { return left_ == 0 && active_ == 0; });
    job_ = nullptr;
    return true;
  }

 private:
  // Runs blocks of the job until none is left; how many it ran.
  std::size_t take_blocks(const std::function<void(std::size_t)>& job, std::size_t blocks) {
    in_block = true;
    std::size_t finished = 0;
    for (std::size_t b; (b = next_.fetch_add(1)) < blocks;) {
      job(b);
      ++finished;
    }
    in_block = false;
    return finished;
  }

  void work() {
    std::uint64_t seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      if (job_ == nullptr) continue;
      const auto* job = job_;
      const std::size_t blocks = blocks_;
      ++active_;
      lock.unlock();
      const std::size_t finished = take_blocks(*job, blocks);
      lock.lock();
      left_ -= finished;
      --active_;
      if (left_ == 0 && active_ == 0) done_.notify_one();
    }
  }

  std::mutex caller_;  // one caller at a time
  std::mutex mutex_;   // guards what follows but next_
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t blocks_ = 0, left_ = 0, active_ = 0;
  std::atomic<std::size_t> next_{0};
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
};

}  // namespace

void run_blocks(std::size_t blocks, const std::function<void(std::size_t)>& block) {
  static Pool pool;
  if (in_block || blocks <= 1 || !pool.run(blocks, block))
    for (std::size_t b = 0; b < blocks; ++b) block(b);
}

}  // namespace knitc::parallel
