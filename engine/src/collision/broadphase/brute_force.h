#pragma once
// The O(n^2) broad phase: every pair of proxies is tested as Aabb::overlaps does at each update()
// (seed 004 "all pairs weakness": n(n-1)/2 tests). It is the reference SweepAndPrune is checked
// and measured against, following Ericson's advice to keep a brute-force variant (seed 004,
// "Tips for debugging a collision detection system").
#include <vector>

#include "rbsim/collision/broadphase/broad_phase.h"
#include "collision/broadphase/proxy_ids.h"

namespace rbsim {

class BruteForce final : public BroadPhase {
 public:
  ProxyId add(const Aabb& box, bool isStatic = false) override;
  void remove(ProxyId id) override;
  void move(ProxyId id, const Aabb& box) override;
  void update() override;
  const std::vector<ProxyPair>& pairs() const override { return pairs_; }
  std::unique_ptr<BroadPhase> clone() const override { return std::make_unique<BruteForce>(*this); }
  std::size_t proxyCount() const override { return ids_.count(); }

 private:
  ProxyIdPool ids_;
  std::vector<Aabb> boxes_;          // by id
  std::vector<bool> isStatic_;       // by id
  std::vector<ProxyPair> pairs_;
};

}  // namespace rbsim
