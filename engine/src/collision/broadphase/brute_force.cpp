#include "collision/broadphase/brute_force.h"

namespace rbsim {

ProxyId BruteForce::add(const Aabb& box, bool isStatic) {
  requireProxyBox(box);
  const ProxyId id = ids_.acquire();
  if (id >= boxes_.size()) {
    boxes_.resize(id + 1);
    isStatic_.resize(id + 1);
  }
  boxes_[id] = box;
  isStatic_[id] = isStatic;
  return id;
}

void BruteForce::remove(ProxyId id) { ids_.release(id); }

void BruteForce::move(ProxyId id, const Aabb& box) {
  ids_.requireAlive(id, "move");
  requireProxyBox(box);
  boxes_[id] = box;
}

void BruteForce::update() {
  // The live proxies, copied into one contiguous array so the n^2 / 2 loop reads consecutive
  // memory: the reference's timings should measure its tests, not cache misses.
  struct Live {
    double min[3], max[3];  // [m]
    ProxyId id;
    bool isStatic;
  };
  std::vector<Live> live;
  live.reserve(ids_.count());
  for (ProxyId id = 0; id < ids_.capacity(); ++id) {
    if (!ids_.alive(id)) continue;
    const Aabb& b = boxes_[id];
    live.push_back({{b.min.x(), b.min.y(), b.min.z()}, {b.max.x(), b.max.y(), b.max.z()}, id, isStatic_[id]});
  }
  // Ids ascend in `live`, so the pairs come out sorted by (a, b) without a sort. Counted as they
  // are found, before the list passes the bound: the old pairs are gone either way.
  pairs_.clear();
  for (std::size_t i = 0; i < live.size(); ++i) {
    const Live& a = live[i];
    for (std::size_t j = i + 1; j < live.size(); ++j) {
      const Live& b = live[j];
      // Aabb::overlaps (closed intervals on all three axes) and the static rule, evaluated in
      // full and branched on once: the result is rarely true, so the branch is predictable.
      const bool hit = (a.min[0] <= b.max[0]) & (b.min[0] <= a.max[0]) & (a.min[1] <= b.max[1]) &
                       (b.min[1] <= a.max[1]) & (a.min[2] <= b.max[2]) & (b.min[2] <= a.max[2]) &
                       !(a.isStatic & b.isStatic);
      if (!hit) continue;
      if (pairs_.size() == kMaxBroadPhasePairs) {
        pairs_.clear();
        throwPairLimit(live.size());
      }
      pairs_.push_back({a.id, b.id});
    }
  }
}

}  // namespace rbsim
