#pragma once
// Settings::threads at work: a loop over independent items shared by the threads of a persistent
// pool (oneTBB's, engine/src/math/parallel_tbb.cpp; issue 54: OpenMP's fork-join per loop spun or
// woke its team for every one of a substep's loops; or, built with RBSIM_WITH_TBB=OFF, one of
// std::threads, parallel_threads.cpp, issue 57). Every item writes only its own slots, so the
// result is the same, bit for bit, for any thread count; the split only decides who computes what.
#include <atomic>
#include <cstddef>
#include <exception>
#include <type_traits>

namespace rbsim {

// Below this many items a loop runs on the calling thread: handing a loop to the pool and waking
// a sleeping thread costs 5 to 20 microseconds, a thousand bodies' integration or a few hundred
// contact points' sweep. Measured (issue 54, docs/speed.md): at 256, two threads were slower than
// one on scenes of 300 to 1000 bodies; at 2048 they are not.
inline constexpr std::size_t kDefaultMinParallelItems = 2048;  // [items]

namespace detail {

// The threshold in force: kDefaultMinParallelItems, unless a test lowered it
// (ScopedMinParallelItems) so that a scene of a few hundred bodies runs every loop on the pool.
std::size_t minParallelItems();

// Sets the threshold for its lifetime and restores the one before (tests only: it is global).
class ScopedMinParallelItems {
 public:
  explicit ScopedMinParallelItems(std::size_t items);
  ~ScopedMinParallelItems();
  ScopedMinParallelItems(const ScopedMinParallelItems&) = delete;
  ScopedMinParallelItems& operator=(const ScopedMinParallelItems&) = delete;

 private:
  std::size_t previous_;
};

// body(context, begin, end) over pieces covering [0, n), on up to `threads` threads of the pool:
// `even` pieces, one a thread (items of equal cost), or one item at a time to whichever thread is
// free (uneven). Returns when every piece has run. The pool's threads sleep between loops.
using RangeBody = void (*)(void* context, std::size_t begin, std::size_t end);
void runOnPool(std::size_t n, int threads, bool even, void* context, RangeBody body);

}  // namespace detail

// f(i) for i in [0, n), on up to `threads` threads. An exception thrown by an item is rethrown on
// the calling thread once every item has run (one of them, when several items throw).
template <typename F>
void parallelFor(std::size_t n, int threads, F&& f) {
  if (threads <= 1 || n < detail::minParallelItems()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  struct Context {
    F& f;
    std::atomic<bool> failed{false};
    std::exception_ptr failure;  // written by the one item that set `failed`
  } context{f, {}, {}};
  detail::runOnPool(n, threads, true, &context, [](void* c, std::size_t begin, std::size_t end) {
    Context& x = *static_cast<Context*>(c);
    for (std::size_t i = begin; i < end; ++i) {
      try {
        x.f(i);
      } catch (...) {
        if (!x.failed.exchange(true)) x.failure = std::current_exception();
      }
    }
  });
  if (context.failure) std::rethrow_exception(context.failure);
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
  detail::runOnPool(n, threads, false, &f, [](void* c, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) (*static_cast<std::remove_reference_t<F>*>(c))(i);
  });
}

}  // namespace rbsim
