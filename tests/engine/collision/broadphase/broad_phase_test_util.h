#pragma once
// Helpers for the broad-phase suites: readable pairs in failure messages, a box from six numbers,
// and Lockstep, which drives SweepAndPrune and the BruteForce reference with one call sequence
// and compares their pairs exactly after every update().
#include <algorithm>
#include <ostream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "collision/broadphase/brute_force.h"
#include "collision/broadphase/sweep_and_prune.h"

namespace rbsim {
inline void PrintTo(const ProxyPair& p, std::ostream* os) { *os << "(" << p.a << "," << p.b << ")"; }
}  // namespace rbsim

namespace rbsim::test {

inline Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {Vec3(x0, y0, z0), Vec3(x1, y1, z1)};
}

inline std::string describe(const std::vector<ProxyPair>& pairs, std::size_t limit = 20) {
  std::ostringstream os;
  for (std::size_t i = 0; i < pairs.size() && i < limit; ++i) os << " (" << pairs[i].a << "," << pairs[i].b << ")";
  if (pairs.size() > limit) os << " ... " << pairs.size() << " in all";
  return os.str();
}

// Sorted by (a, b), a < b, no duplicates, never two statics.
inline testing::AssertionResult wellFormed(const std::vector<ProxyPair>& pairs, const std::vector<bool>& isStatic) {
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ProxyPair& p = pairs[i];
    if (p.a >= p.b) return testing::AssertionFailure() << "pair (" << p.a << "," << p.b << ") has a >= b";
    if (i > 0 && !(pairs[i - 1] < p)) return testing::AssertionFailure() << "pairs not strictly sorted at " << i;
    if (p.b < isStatic.size() && isStatic[p.a] && isStatic[p.b])
      return testing::AssertionFailure() << "static-static pair (" << p.a << "," << p.b << ")";
  }
  return testing::AssertionSuccess();
}

class Lockstep {
 public:
  ProxyId add(const Aabb& b, bool isStatic = false) {
    const ProxyId id = sap.add(b, isStatic);
    const ProxyId reference = bf.add(b, isStatic);
    EXPECT_EQ(id, reference) << "the two broad phases handed out different ids";
    if (id >= isStatic_.size()) isStatic_.resize(id + 1);
    isStatic_[id] = isStatic;
    alive_.push_back(id);
    return id;
  }
  void remove(ProxyId id) {
    sap.remove(id);
    bf.remove(id);
    alive_.erase(std::find(alive_.begin(), alive_.end(), id));
  }
  void move(ProxyId id, const Aabb& b) {
    sap.move(id, b);
    bf.move(id, b);
  }
  // Updates both and compares: the pair lists must be equal element for element.
  testing::AssertionResult update() {
    sap.update();
    bf.update();
    if (auto ok = wellFormed(sap.pairs(), isStatic_); !ok) return ok;
    if (sap.proxyCount() != bf.proxyCount()) return testing::AssertionFailure() << "proxy counts differ";
    if (sap.pairs() == bf.pairs()) return testing::AssertionSuccess();
    std::vector<ProxyPair> extra, missing;
    std::set_difference(sap.pairs().begin(), sap.pairs().end(), bf.pairs().begin(), bf.pairs().end(),
                        std::back_inserter(extra));
    std::set_difference(bf.pairs().begin(), bf.pairs().end(), sap.pairs().begin(), sap.pairs().end(),
                        std::back_inserter(missing));
    return testing::AssertionFailure() << "sweep and prune differs from brute force (" << sap.pairs().size()
                                       << " vs " << bf.pairs().size() << " pairs)\n  extra:" << describe(extra)
                                       << "\n  missing:" << describe(missing);
  }
  const std::vector<ProxyId>& alive() const { return alive_; }  // in order of addition
  bool isStatic(ProxyId id) const { return isStatic_[id]; }

  SweepAndPrune sap;
  BruteForce bf;

 private:
  std::vector<ProxyId> alive_;
  std::vector<bool> isStatic_;
};

}  // namespace rbsim::test
