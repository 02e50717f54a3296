// collision/broadphase: hand-made scenes with their expected pairs written out, run against both
// broad phases (SweepAndPrune and the BruteForce reference), so each is checked on its own and
// not only against the other.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "broad_phase_test_util.h"

namespace rbsim {
namespace {

using test::box;
using Pairs = std::vector<ProxyPair>;

template <typename T>
class BroadPhaseCases : public testing::Test {
 protected:
  T bp;
  const Pairs& updated() {
    bp.update();
    return bp.pairs();
  }
};
using Implementations = testing::Types<SweepAndPrune, BruteForce>;
// Names the instantiations in test output; it is also the third argument of TYPED_TEST_SUITE,
// without which clang's -Wpedantic warns about an empty variadic macro argument.
struct ImplementationName {
  template <typename T>
  static std::string GetName(int) {
    return std::is_same_v<T, SweepAndPrune> ? "SweepAndPrune" : "BruteForce";
  }
};
TYPED_TEST_SUITE(BroadPhaseCases, Implementations, ImplementationName);

const Aabb kUnit = box(0, 0, 0, 1, 1, 1);

TYPED_TEST(BroadPhaseCases, NoProxiesNoPairs) {
  EXPECT_EQ(this->updated(), Pairs{});
  EXPECT_EQ(this->bp.proxyCount(), 0u);
}

TYPED_TEST(BroadPhaseCases, OneProxyNoPairs) {
  EXPECT_EQ(this->bp.add(kUnit), 0u);
  EXPECT_EQ(this->updated(), Pairs{});
  EXPECT_EQ(this->bp.proxyCount(), 1u);
}

TYPED_TEST(BroadPhaseCases, TwoOverlappingAndTwoApart) {
  this->bp.add(kUnit);
  this->bp.add(box(0.5, 0.5, 0.5, 1.5, 1.5, 1.5));
  this->bp.add(box(5, 5, 5, 6, 6, 6));
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}}));
}

// Apart on one axis is enough to be apart, however much the other two overlap.
TYPED_TEST(BroadPhaseCases, OverlapOnTwoAxesIsNotOverlap) {
  this->bp.add(kUnit);
  this->bp.add(box(0, 0, 2, 1, 1, 3));
  this->bp.add(box(-5, 0.2, 0.2, 5, 0.8, 0.8));  // crosses 0 in x, inside 0 in y and z
  EXPECT_EQ(this->updated(), (Pairs{{0, 2}}));
}

// The 26 neighbours of a unit cube on the integer lattice share a face, an edge or a corner with
// it (exactly equal coordinates): closed intervals, so all overlap. Moved apart by the smallest
// representable gap, none does.
TYPED_TEST(BroadPhaseCases, TouchingFacesEdgesAndCorners) {
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        SCOPED_TRACE(testing::Message() << "neighbour (" << dx << "," << dy << "," << dz << ")");
        TypeParam touching;
        touching.add(kUnit);
        const Vec3 d(dx, dy, dz);
        touching.add({kUnit.min + d, kUnit.max + d});
        touching.update();
        EXPECT_EQ(touching.pairs(), (Pairs{{0, 1}}));

        TypeParam apart;
        apart.add(kUnit);
        Vec3 shift = d;
        for (int k = 0; k < 3; ++k) {
          if (d[k] > 0) shift[k] = std::nextafter(1.0, 2.0);
          if (d[k] < 0) shift[k] = -std::nextafter(1.0, 2.0);
        }
        apart.add({kUnit.min + shift, kUnit.max + shift});
        apart.update();
        EXPECT_EQ(apart.pairs(), Pairs{});
      }
    }
  }
}

TYPED_TEST(BroadPhaseCases, NestedAndIdenticalBoxes) {
  this->bp.add(box(0, 0, 0, 10, 10, 10));
  this->bp.add(box(4, 4, 4, 5, 5, 5));  // inside 0
  this->bp.add(box(4, 4, 4, 5, 5, 5));  // identical to 1
  this->bp.add(box(20, 0, 0, 21, 1, 1));
  this->bp.add(box(20, 0, 0, 21, 1, 1));  // identical to 3
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}, {0, 2}, {1, 2}, {3, 4}}));
}

// A overlaps B, B overlaps C, A does not reach C: overlap is not transitive.
TYPED_TEST(BroadPhaseCases, Chain) {
  this->bp.add(box(0, 0, 0, 1, 1, 1));
  this->bp.add(box(0.5, 0, 0, 1.5, 1, 1));
  this->bp.add(box(1.2, 0, 0, 2.2, 1, 1));
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}, {1, 2}}));
}

TYPED_TEST(BroadPhaseCases, ZeroThicknessBoxes) {
  this->bp.add(box(0, 0, 0.5, 1, 1, 0.5));  // 0: a square in z = 0.5
  this->bp.add(kUnit);                      // 1: the square lies inside it
  this->bp.add(box(0, 0, 1, 1, 1, 1));      // 2: a square on 1's top face, apart from 0 in z
  this->bp.add(box(3, 3, 3, 3, 3, 3));      // 3: a point
  this->bp.add(box(3, 3, 3, 3, 3, 3));      // 4: the same point
  this->bp.add(box(1, 1, 1, 1, 1, 1));      // 5: a point on 1's corner and 2's corner
  this->bp.add(box(3, 3, 0, 3, 3, 2.9));    // 6: a segment ending just short of point 3
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}, {1, 2}, {1, 5}, {2, 5}, {3, 4}}));
}

TYPED_TEST(BroadPhaseCases, StaticPairsNeverReported) {
  this->bp.add(box(0, 0, 0, 10, 1, 10), true);    // 0: floor
  this->bp.add(box(5, 0, 5, 6, 3, 6), true);      // 1: pillar on the floor
  this->bp.add(box(5.5, 0.5, 5.5, 7, 2, 7));      // 2: dynamic, overlapping both
  this->bp.add(box(20, 20, 20, 21, 21, 21));      // 3: dynamic, alone
  this->bp.add(box(20.5, 20.5, 20.5, 22, 22, 22));  // 4: dynamic, on 3
  EXPECT_EQ(this->updated(), (Pairs{{0, 2}, {1, 2}, {3, 4}}));
}

TYPED_TEST(BroadPhaseCases, MoveChangesPairsAtUpdate) {
  this->bp.add(kUnit);
  const ProxyId b = this->bp.add(box(3, 0, 0, 4, 1, 1));
  EXPECT_EQ(this->updated(), Pairs{});
  // Slide b through a along x, one step at a time: apart, touching, inside, touching, apart.
  const double starts[] = {2, 1, 0.25, -1, -2};
  const Pairs expected[] = {{}, {{0, 1}}, {{0, 1}}, {{0, 1}}, {}};
  for (int i = 0; i < 5; ++i) {
    this->bp.move(b, box(starts[i], 0, 0, starts[i] + 1, 1, 1));
    EXPECT_EQ(this->updated(), expected[i]) << "b starting at x = " << starts[i];
  }
  // Jump back across: still exact.
  this->bp.move(b, box(100, 0, 0, 101, 1, 1));
  EXPECT_EQ(this->updated(), Pairs{});
  this->bp.move(b, box(0.5, 0.5, 0.5, 0.6, 0.6, 0.6));
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}}));
}

TYPED_TEST(BroadPhaseCases, PairsChangeOnlyAtUpdate) {
  this->bp.add(kUnit);
  this->bp.add(kUnit);
  EXPECT_EQ(this->bp.pairs(), Pairs{});
  this->bp.update();
  this->bp.move(1, box(5, 5, 5, 6, 6, 6));
  EXPECT_EQ(this->bp.pairs(), (Pairs{{0, 1}}));
  EXPECT_EQ(this->updated(), Pairs{});
}

TYPED_TEST(BroadPhaseCases, RemoveDropsPairsAndIdsAreReused) {
  this->bp.add(box(0, 0, 0, 1, 1, 1));
  this->bp.add(box(0.5, 0, 0, 1.5, 1, 1));
  this->bp.add(box(1.2, 0, 0, 2.2, 1, 1));
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}, {1, 2}}));
  this->bp.remove(1);
  EXPECT_EQ(this->updated(), Pairs{});
  EXPECT_EQ(this->bp.proxyCount(), 2u);
  // The freed id comes back, for a box far from where proxy 1 was.
  EXPECT_EQ(this->bp.add(box(2, 0, 0, 3, 1, 1)), 1u);
  EXPECT_EQ(this->updated(), (Pairs{{1, 2}}));
  // Smallest free id first.
  this->bp.remove(2);
  this->bp.remove(0);
  EXPECT_EQ(this->bp.add(kUnit), 0u);
  EXPECT_EQ(this->bp.add(kUnit), 2u);
  EXPECT_EQ(this->bp.add(kUnit), 3u);
  EXPECT_EQ(this->updated(), (Pairs{{0, 2}, {0, 3}, {2, 3}}));
}

// Removing and re-adding an id between two updates: the new proxy's box counts, not the old one.
TYPED_TEST(BroadPhaseCases, RemoveAndReaddBeforeUpdate) {
  this->bp.add(kUnit);
  this->bp.add(box(0.5, 0.5, 0.5, 2, 2, 2));
  this->bp.add(box(10, 10, 10, 11, 11, 11));
  EXPECT_EQ(this->updated(), (Pairs{{0, 1}}));
  this->bp.remove(1);
  EXPECT_EQ(this->bp.add(box(10.5, 10.5, 10.5, 12, 12, 12)), 1u);
  EXPECT_EQ(this->updated(), (Pairs{{1, 2}}));
  // Add then remove before an update: it never appears.
  const ProxyId ghost = this->bp.add(kUnit);
  this->bp.remove(ghost);
  EXPECT_EQ(this->updated(), (Pairs{{1, 2}}));
  EXPECT_EQ(this->bp.proxyCount(), 3u);
}

TYPED_TEST(BroadPhaseCases, BadInputThrows) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(this->bp.add(box(0, 0, 0, nan, 1, 1)), std::invalid_argument);
  EXPECT_THROW(this->bp.add(box(-inf, 0, 0, inf, 1, 1)), std::invalid_argument);
  EXPECT_THROW(this->bp.add(box(0, 2, 0, 1, 1, 1)), std::invalid_argument);  // min > max
  EXPECT_THROW(this->bp.add(Aabb{}), std::invalid_argument);                 // the empty box
  EXPECT_EQ(this->bp.proxyCount(), 0u);
  const ProxyId id = this->bp.add(kUnit);
  EXPECT_THROW(this->bp.move(id, box(0, 0, 0, 1, nan, 1)), std::invalid_argument);
  EXPECT_THROW(this->bp.move(id + 1, kUnit), std::out_of_range);
  EXPECT_THROW(this->bp.remove(id + 1), std::out_of_range);
  this->bp.remove(id);
  EXPECT_THROW(this->bp.remove(id), std::out_of_range);
  EXPECT_THROW(this->bp.move(id, kUnit), std::out_of_range);
  EXPECT_EQ(this->updated(), Pairs{});
}

}  // namespace
}  // namespace rbsim
