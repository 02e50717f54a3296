// detail::runOnPool on oneTBB's persistent pool (RBSIM_WITH_TBB=ON, the default; issue 54).
// parallel_threads.cpp is the same contract on std::thread, for platforms without oneTBB.
#include <map>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "rbsim/math/parallel.h"

namespace rbsim::detail {

namespace {

// One arena per thread count a World asked for, made on first use and kept: oneTBB's workers
// live for the process and sleep when no arena has work (issue 54's persistent pool). Never
// destroyed, so no World stepping during static destruction finds its arena gone.
tbb::task_arena& arenaFor(int threads) {
  static std::mutex mutex;
  static auto* arenas = new std::map<int, std::unique_ptr<tbb::task_arena>>();
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<tbb::task_arena>& arena = (*arenas)[threads];
  if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
  return *arena;
}

}  // namespace

void runOnPool(std::size_t n, int threads, bool even, void* context, RangeBody body) {
  arenaFor(threads).execute([&] {
    const auto piece = [&](const tbb::blocked_range<std::size_t>& r) { body(context, r.begin(), r.end()); };
    if (even) {
      // Equal contiguous blocks, one a thread, as OpenMP's schedule(static) split them.
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), piece, tbb::static_partitioner());
    } else {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), piece, tbb::simple_partitioner());
    }
  });
}

}  // namespace rbsim::detail
