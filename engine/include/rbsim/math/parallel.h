#pragma once
// Settings::threads at work: a loop over independent items shared by OpenMP's threads. Every
// item writes only its own slots, so the result is the same, bit for bit, for any thread count;
// the split (static: equal contiguous blocks) only decides who computes what.
#include <cstddef>
#include <exception>

namespace rbsim {

// Below this many items a loop runs on the calling thread: waking the pool costs a few
// microseconds, more than a few hundred bodies' or contact points' work.
inline constexpr std::size_t kMinParallelItems = 256;  // [items]

// f(i) for i in [0, n), on up to `threads` threads. An exception thrown by an item is rethrown on
// the calling thread once every thread has finished (one of them, when several items throw).
template <typename F>
void parallelFor(std::size_t n, int threads, F&& f) {
  if (threads <= 1 || n < kMinParallelItems) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::exception_ptr failure;
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    try {
      f(static_cast<std::size_t>(i));
    } catch (...) {
#pragma omp critical(rbsim_parallel_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

// f(i) for i in [0, n) on up to `threads` threads, each thread taking the next item when it is
// done (items of uneven cost, such as islands, whose results do not depend on who runs them). Runs
// on the calling thread when `parallel` is false. Items must not throw.
template <typename F>
void parallelForUneven(std::size_t n, int threads, bool parallel, F&& f) {
  if (threads <= 1 || n < 2 || !parallel) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (std::ptrdiff_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
}

}  // namespace rbsim
