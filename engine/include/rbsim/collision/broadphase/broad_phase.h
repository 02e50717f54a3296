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

// The most overlapping pairs a broad phase lists [pairs]. Each pair costs about 2 KB on its way
// through the narrow phase (a 296-byte contact slot, a 560-byte recycling frame, their copies
// kept for the next step) and the solver, so the bound holds that to ~8 GB. Boxes resting side
// by side list 4 pairs a box (its margin-inflated bounds meet its 8 neighbours'), stacked in a
// cube 13: 1e6 boxes in a layer or 3e5 in a block fit. 1e5 boxes at one point overlap in 5e9
// pairs, which ended in std::bad_alloc. update() throws StepLimitError
// (integrate/simulation_error.h) before it lists more.
constexpr std::size_t kMaxBroadPhasePairs = std::size_t{1} << 22;
// The most contacts a narrow phase lists [manifolds]: as many as pairs, for the same memory (a
// pair of compounds gives one per pair of children, up to 128^2).
constexpr std::size_t kMaxStepContacts = kMaxBroadPhasePairs;

// An overlapping pair, a < b. Pairs of two static proxies are never reported.
struct ProxyPair {
  ProxyId a = 0, b = 0;
  friend bool operator==(const ProxyPair& x, const ProxyPair& y) { return x.a == y.a && x.b == y.b; }
  friend bool operator<(const ProxyPair& x, const ProxyPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }
};
// 8 bytes, 8 pairs a cache line: the broad phase lists up to kMaxBroadPhasePairs of them a step.
static_assert(sizeof(ProxyPair) == 8, "ProxyPair's size: see the comment above");

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  // Ids are reused after remove(). A static proxy never moves and never pairs with another static.
  // Like move(), add() and remove() change pairs() only at the next update(). A box must be
  // finite with min <= max (std::invalid_argument otherwise); an unknown id is std::out_of_range.
  virtual ProxyId add(const Aabb& box, bool isStatic = false) = 0;
  virtual void remove(ProxyId id) = 0;
  virtual void move(ProxyId id, const Aabb& box) = 0;  // new box; takes effect at update()
  // Brings pairs() up to date. Throws StepLimitError when the boxes overlap in more than
  // kMaxBroadPhasePairs pairs, before listing more, and leaves pairs() empty; the proxies stay as
  // they were given, and the next update() lists their pairs afresh.
  virtual void update() = 0;
  // The overlapping pairs after the last update(), sorted by (a, b), no duplicates.
  virtual const std::vector<ProxyPair>& pairs() const = 0;
  virtual std::size_t proxyCount() const = 0;
  // A deep copy: the same proxies, boxes and pairs, going on alone (World's copy, a saved state).
  virtual std::unique_ptr<BroadPhase> clone() const = 0;
};

}  // namespace rbsim
