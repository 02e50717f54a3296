// collision/broadphase/slab_mask: overlapping intervals must always share a mask bit (the masks
// only ever reject pairs that are apart), including touching ends on slab boundaries, negative
// coordinates, zero-length intervals, long intervals and coordinates too large for exact slabs.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "collision/broadphase/slab_mask.h"

namespace rbsim {
namespace {

constexpr double kInvWidth = 0.5;  // [1/m] slabs 2 m wide

TEST(SlabMask, ExactValues) {
  EXPECT_EQ(slabMask(0.0, 0.0, kInvWidth), 0x01u);    // slab 0
  EXPECT_EQ(slabMask(0.0, 1.99, kInvWidth), 0x01u);   // still slab 0
  EXPECT_EQ(slabMask(0.0, 2.0, kInvWidth), 0x03u);    // slabs 0 and 1
  EXPECT_EQ(slabMask(-0.5, -0.1, kInvWidth), 0x80u);  // slab -1 is bit 7
  EXPECT_EQ(slabMask(14.0, 18.0, kInvWidth), 0x83u);  // slabs 7, 8, 9: bits 7, 0, 1
  EXPECT_EQ(slabMask(0.0, 13.9, kInvWidth), 0x7fu);   // slabs 0..6
  EXPECT_EQ(slabMask(0.0, 14.0, kInvWidth), 0xffu);   // eight slabs: all bits
  EXPECT_EQ(slabMask(-1e300, 0.0, kInvWidth), 0xffu);  // beyond exact slab numbers: all bits
}

TEST(SlabMask, OverlappingIntervalsShareABit) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> pos(-40.0, 40.0), len(0.0, 5.0);
  std::uniform_int_distribution<int> lattice(-20, 20), latticeLen(0, 3);
  std::bernoulli_distribution onLattice(0.5);
  int overlapping = 0, rejected = 0;
  for (int i = 0; i < 200000; ++i) {
    double a0, a1, b0, b1;
    if (onLattice(rng)) {  // integer ends: touching on slab boundaries (even numbers) is common
      a0 = lattice(rng), a1 = a0 + latticeLen(rng), b0 = lattice(rng), b1 = b0 + latticeLen(rng);
    } else {
      a0 = pos(rng), a1 = a0 + len(rng), b0 = pos(rng), b1 = b0 + len(rng);
    }
    const bool overlap = a0 <= b1 && b0 <= a1;
    const bool share = (slabMask(a0, a1, kInvWidth) & slabMask(b0, b1, kInvWidth)) != 0;
    if (overlap) {
      ++overlapping;
      ASSERT_TRUE(share) << "[" << a0 << ", " << a1 << "] and [" << b0 << ", " << b1 << "]";
    } else if (!share) {
      ++rejected;
    }
  }
  EXPECT_GT(overlapping, 10000);
  EXPECT_GT(rejected, 100000) << "the masks should reject most pairs that are apart";
}

}  // namespace
}  // namespace rbsim
