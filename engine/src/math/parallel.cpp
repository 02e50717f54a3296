#include "rbsim/math/parallel.h"

#include <atomic>

namespace rbsim::detail {

namespace {

std::atomic<std::size_t> threshold{kDefaultMinParallelItems};  // [items]

}  // namespace

std::size_t minParallelItems() { return threshold.load(std::memory_order_relaxed); }

ScopedMinParallelItems::ScopedMinParallelItems(std::size_t items) : previous_(threshold.exchange(items)) {}

ScopedMinParallelItems::~ScopedMinParallelItems() { threshold.store(previous_); }

}  // namespace rbsim::detail
