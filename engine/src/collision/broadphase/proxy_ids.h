#pragma once
// What every broad phase does the same way with its proxies: hand out ids and check the boxes it
// is given. Sharing it is what lets the tests drive SweepAndPrune and BruteForce with one call
// sequence and compare their pairs id for id.
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim {

// Ids are dense indices into per-proxy arrays; the smallest free id is reused first, so the ids
// (and the pairs, which are sorted by id) depend only on the sequence of add() and remove() calls.
class ProxyIdPool {
 public:
  ProxyId acquire() {
    ++count_;
    if (!free_.empty()) {
      const ProxyId id = free_.top();
      free_.pop();
      alive_[id] = true;
      return id;
    }
    alive_.push_back(true);
    return static_cast<ProxyId>(alive_.size() - 1);
  }
  void release(ProxyId id) {
    requireAlive(id, "remove");
    alive_[id] = false;
    free_.push(id);
    --count_;
  }
  bool alive(ProxyId id) const { return id < alive_.size() && alive_[id]; }
  void requireAlive(ProxyId id, const char* operation) const {
    if (!alive(id)) {
      throw std::out_of_range(std::string("broad phase ") + operation + ": no proxy " + std::to_string(id));
    }
  }
  std::size_t count() const { return count_; }
  std::size_t capacity() const { return alive_.size(); }  // one past the largest id ever handed out

 private:
  std::vector<bool> alive_;
  std::priority_queue<ProxyId, std::vector<ProxyId>, std::greater<ProxyId>> free_;
  std::size_t count_ = 0;
};

// A proxy's box must be finite and non-empty (min <= max on every axis; zero thickness is
// allowed). NaN would break any sorted order, and infinite boxes (planes) are not proxies: the
// World tests them separately.
inline void requireProxyBox(const Aabb& box) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(box.min[k]) || !std::isfinite(box.max[k]))
      throw std::invalid_argument("broad phase: a proxy box must be finite");
    if (box.min[k] > box.max[k]) throw std::invalid_argument("broad phase: a proxy box must not be empty (min > max)");
  }
}

// What both broad phases say when the boxes overlap in more pairs than a step may hold.
[[noreturn]] inline void throwPairLimit(std::size_t proxies) {
  throw StepLimitError("the bounding boxes of " + std::to_string(proxies) + " bodies overlap in more than " +
                       std::to_string(kMaxBroadPhasePairs) +
                       " pairs, the most a step holds (kMaxBroadPhasePairs, ~8 GB of contacts): bodies are piled into "
                       "one place; expected them spread out (their positions, a spawner's region and count)");
}

// The key of pair (a, b), a < b: sorting keys sorts pairs by (a, b).
inline std::uint64_t pairKey(ProxyId a, ProxyId b) {
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}
inline ProxyPair pairOfKey(std::uint64_t key) {
  return {static_cast<ProxyId>(key >> 32), static_cast<ProxyId>(key & 0xffffffffu)};
}

}  // namespace rbsim
