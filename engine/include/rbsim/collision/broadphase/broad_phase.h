#pragma once
// The broad phase interface (seed 004 "two-phase collision detection"): proxies with world AABBs
// in, the set of overlapping proxy pairs out. SweepAndPrune is the fast one, BruteForce the
// O(n^2) reference the tests and benchmarks compare it with; both give exactly the same pairs.
#include <cstdint>
#include <memory>
#include <vector>

#include "rbsim/geometry/aabb.h"

namespace rbsim {

using ProxyId = std::uint32_t;

// An overlapping pair, a < b. Pairs of two static proxies are never reported.
struct ProxyPair {
  ProxyId a = 0, b = 0;
  friend bool operator==(const ProxyPair& x, const ProxyPair& y) { return x.a == y.a && x.b == y.b; }
  friend bool operator<(const ProxyPair& x, const ProxyPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }
};

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  // Ids are reused after remove(). A static proxy never moves and never pairs with another static.
  // Like move(), add() and remove() change pairs() only at the next update(). A box must be
  // finite with min <= max (std::invalid_argument otherwise); an unknown id is std::out_of_range.
  virtual ProxyId add(const Aabb& box, bool isStatic = false) = 0;
  virtual void remove(ProxyId id) = 0;
  virtual void move(ProxyId id, const Aabb& box) = 0;  // new box; takes effect at update()
  virtual void update() = 0;                           // brings pairs() up to date
  // The overlapping pairs after the last update(), sorted by (a, b), no duplicates.
  virtual const std::vector<ProxyPair>& pairs() const = 0;
  virtual std::size_t proxyCount() const = 0;
  // A deep copy: the same proxies, boxes and pairs, going on alone (World's copy, a saved state).
  virtual std::unique_ptr<BroadPhase> clone() const = 0;
};

}  // namespace rbsim
