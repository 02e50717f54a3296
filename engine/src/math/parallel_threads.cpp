// detail::runOnPool on std::thread (RBSIM_WITH_TBB=OFF, issue 57): for platforms without oneTBB,
// such as mingw-w64, the contract of parallel_tbb.cpp with the standard library alone. The pool's
// threads are made on first use, kept for the process (never destroyed, as oneTBB's arenas, so no
// World stepping during static destruction finds them gone) and sleep on a condition variable
// between loops. The pool runs one loop at a time: a loop asked for while another runs (a second
// World stepping on another thread, or a loop inside an item) runs on its calling thread, which
// gives the same result, since every item writes only its own slots.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "rbsim/math/parallel.h"

namespace rbsim::detail {

namespace {

class ThreadPool {
 public:
  // body over [0, n) on the calling thread and `threads` - 1 of the pool's; false, having run
  // nothing, when the pool is busy with another loop.
  bool tryRun(std::size_t n, int threads, bool even, void* context, RangeBody body) {
    const std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      while (workers_.size() + 1 < static_cast<std::size_t>(threads)) {
        workers_.emplace_back(&ThreadPool::work, this, static_cast<int>(workers_.size()) + 1, generation_);
      }
      n_ = n;
      participants_ = threads;
      even_ = even;
      context_ = context;
      body_ = body;
      next_.store(0);
      pending_ = threads - 1;
      ++generation_;
    }
    wake_.notify_all();
    share(0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    return true;
  }

 private:
  // Worker `participant` (1, 2, ...): sleeps until a loop starts, takes its share when the loop
  // has that many participants, and says when it is done.
  void work(int participant, std::uint64_t seen) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return generation_ != seen; });
      seen = generation_;
      if (participant >= participants_) continue;
      lock.unlock();
      share(participant);
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  // One participant's part of the loop in progress: its contiguous block of [0, n) when the items
  // cost the same (even), else the next item not yet taken until none is left.
  void share(int participant) {
    if (even_) {
      const std::size_t p = static_cast<std::size_t>(participant), count = static_cast<std::size_t>(participants_);
      const std::size_t begin = n_ * p / count, end = n_ * (p + 1) / count;
      if (begin < end) body_(context_, begin, end);
      return;
    }
    for (std::size_t i = next_.fetch_add(1); i < n_; i = next_.fetch_add(1)) body_(context_, i, i + 1);
  }

  std::mutex busy_;   // held by the caller of the loop in progress
  std::mutex mutex_;  // guards the fields below between the caller and the workers
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;  // worker k is participant k + 1; the caller is 0
  std::uint64_t generation_ = 0;      // loops started, so a worker knows a new one from the last
  int pending_ = 0;                   // workers still on the loop in progress
  // The loop in progress, set before its generation starts and read by its participants.
  std::size_t n_ = 0;
  int participants_ = 1;
  bool even_ = true;
  void* context_ = nullptr;
  RangeBody body_ = nullptr;
  std::atomic<std::size_t> next_{0};  // the next item an uneven loop hands out
};

}  // namespace

void runOnPool(std::size_t n, int threads, bool even, void* context, RangeBody body) {
  static auto* pool = new ThreadPool();
  if (!pool->tryRun(n, threads, even, context, body)) body(context, 0, n);
}

}  // namespace rbsim::detail
