// The broad phases' bound on pairs (broad_phase.h kMaxBroadPhasePairs): boxes overlapping in more
// pairs are refused by update() before it lists them (1e5 boxes at one point overlapped in 5e9
// pairs and ended in std::bad_alloc), exactly at the bound, and the next update() after a refusal
// lists the pairs of the boxes it is given as if nothing had happened.
#include <gtest/gtest.h>

#include "broad_phase_test_util.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim {
namespace {

// Boxes all overlapping: n (n - 1) / 2 pairs. The most within the bound, and the fewest past it.
std::size_t mostWithinThePairLimit() {
  std::size_t n = 2;
  while ((n + 1) * n / 2 <= kMaxBroadPhasePairs) ++n;
  return n;
}

constexpr double kPitch = 2.0;  // [m] between spread boxes of side 1: apart

Aabb spread(std::size_t k) {
  const double x = kPitch * static_cast<double>(k);
  return test::box(x, 0, 0, x + 1, 1, 1);
}
Aabb piled() { return test::box(0, 0, 0, 1, 1, 1); }

template <class Phase>
void expectRefusedPastTheBound() {
  const std::size_t within = mostWithinThePairLimit();
  Phase phase;
  for (std::size_t k = 0; k < within; ++k) phase.add(piled());
  phase.update();
  EXPECT_EQ(phase.pairs().size(), within * (within - 1) / 2);
  EXPECT_LE(phase.pairs().size(), kMaxBroadPhasePairs);
  phase.add(piled());
  try {
    phase.update();
    FAIL() << "pairs past the bound were listed";
  } catch (const StepLimitError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the bounding boxes of " + std::to_string(within + 1) + " bodies overlap in more than " +
                           std::to_string(kMaxBroadPhasePairs) + " pairs"),
              std::string::npos)
        << message;
  }
  EXPECT_TRUE(phase.pairs().empty());
}

TEST(PairLimit, SweepAndPruneRefusesPastTheBoundAndNotBefore) { expectRefusedPastTheBound<SweepAndPrune>(); }
TEST(PairLimit, BruteForceRefusesPastTheBoundAndNotBefore) { expectRefusedPastTheBound<BruteForce>(); }

// Spread, piled (refused: both by jumping there, a rebuild, and by growing in place, which the
// incremental sort predicts as cheap), then spread again: the pairs after a refusal are exact.
TEST(PairLimit, AfterARefusalTheNextUpdateFindsThePairsAfresh) {
  const std::size_t n = mostWithinThePairLimit() + 1;
  test::Lockstep lock;
  for (std::size_t k = 0; k < n; ++k) lock.add(spread(k));
  ASSERT_TRUE(lock.update());
  EXPECT_TRUE(lock.sap.pairs().empty());
  for (ProxyId id : lock.alive()) lock.move(id, piled());
  EXPECT_THROW(lock.sap.update(), StepLimitError);
  EXPECT_THROW(lock.bf.update(), StepLimitError);
  // Neighbours overlapping: each box grown to reach the next one.
  for (std::size_t k = 0; k < n; ++k) {
    Aabb b = spread(k);
    b.max.x() += kPitch;
    lock.move(lock.alive()[k], b);
  }
  ASSERT_TRUE(lock.update());
  EXPECT_EQ(lock.sap.pairs().size(), n - 1);
  // Grown in place over the whole row, centres still: refused again.
  for (std::size_t k = 0; k < n; ++k) lock.move(lock.alive()[k], test::box(-1, 0, 0, kPitch * static_cast<double>(n), 1, 1));
  EXPECT_THROW(lock.sap.update(), StepLimitError);
  EXPECT_THROW(lock.bf.update(), StepLimitError);
  // Proxies added and removed across a refusal are taken in by the next update.
  lock.remove(lock.alive()[0]);
  lock.remove(lock.alive()[0]);
  for (std::size_t k = 0; k < n - 2; ++k) lock.move(lock.alive()[k], spread(k));
  lock.add(spread(n + 5));
  ASSERT_TRUE(lock.update());
  EXPECT_TRUE(lock.sap.pairs().empty());
  // And the incremental updates after it stay exact.
  for (std::size_t k = 0; k + 1 < lock.alive().size(); k += 2) lock.move(lock.alive()[k], spread(k + 1));
  ASSERT_TRUE(lock.update());
  EXPECT_FALSE(lock.sap.pairs().empty());
}

}  // namespace
}  // namespace rbsim
