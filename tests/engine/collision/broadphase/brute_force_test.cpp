// collision/broadphase/brute_force: the reference itself, against the plainest possible code (a
// double loop calling Aabb::overlaps), on lattice scenes full of exactly touching, identical and
// zero-thickness boxes, with statics, removals and reused ids.
#include <random>

#include <gtest/gtest.h>

#include "broad_phase_test_util.h"

namespace rbsim {
namespace {

TEST(BruteForce, EqualsAabbOverlapsOverAllPairs) {
  for (unsigned seed : {21u, 22u, 23u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pos(0, 8), size(0, 2);
    std::bernoulli_distribution isStatic(0.2), removed(0.1);
    BruteForce bf;
    std::vector<Aabb> boxes;
    std::vector<bool> statics, alive;
    for (int i = 0; i < 400; ++i) {
      Aabb b;
      for (int k = 0; k < 3; ++k) {
        b.min[k] = pos(rng);
        b.max[k] = b.min[k] + size(rng);
      }
      statics.push_back(isStatic(rng));
      EXPECT_EQ(bf.add(b, statics.back()), static_cast<ProxyId>(i));
      boxes.push_back(b);
      alive.push_back(true);
    }
    for (ProxyId id = 0; id < boxes.size(); ++id) {
      if (removed(rng)) {
        bf.remove(id);
        alive[id] = false;
      }
    }
    bf.update();
    std::vector<ProxyPair> expected;
    for (ProxyId a = 0; a < boxes.size(); ++a) {
      for (ProxyId b = a + 1; b < boxes.size(); ++b) {
        if (alive[a] && alive[b] && !(statics[a] && statics[b]) && boxes[a].overlaps(boxes[b])) {
          expected.push_back({a, b});
        }
      }
    }
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(bf.pairs(), expected) << "brute force:" << test::describe(bf.pairs())
                                    << "\nexpected:" << test::describe(expected);
  }
}

}  // namespace
}  // namespace rbsim
