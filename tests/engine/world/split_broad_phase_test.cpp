// world/split_broad_phase.h (issue 58): the awake proxies' pairs, with each other and with the
// resting ones, are exactly those of the boxes, as brute force finds them, whatever sequence of
// wakes, sleeps, adds, removals and moves led there, with either broad phase for the awake set.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "world/split_broad_phase.h"

namespace rbsim {
namespace {

constexpr int kProxies = 300;
constexpr int kUpdates = 60;
constexpr double kWorldSize = 20.0;  // [m] the boxes' centres lie in a cube of this side
constexpr double kMaxHalf = 0.8;     // [m] largest half extent

Aabb randomBox(std::mt19937& rng) {
  std::uniform_real_distribution<double> centre(0.0, kWorldSize), half(0.05, kMaxHalf);
  const Vec3 c(centre(rng), centre(rng), centre(rng));
  const Vec3 h(half(rng), half(rng), half(rng));
  return {c - h, c + h};
}

// Every pair of live proxies, one of them awake, whose boxes overlap: sorted by (a, b).
std::vector<ProxyPair> bruteForce(const std::vector<Aabb>& boxes, const std::vector<char>& alive, const std::vector<char>& awake) {
  std::vector<ProxyPair> pairs;
  for (ProxyId a = 0; a < boxes.size(); ++a) {
    for (ProxyId b = a + 1; b < boxes.size(); ++b) {
      if (!alive[a] || !alive[b] || (!awake[a] && !awake[b])) continue;
      if (boxes[a].overlaps(boxes[b])) pairs.push_back({a, b});
    }
  }
  return pairs;
}

class SplitBroadPhaseTest : public ::testing::TestWithParam<Settings::BroadPhaseMethod> {};

TEST_P(SplitBroadPhaseTest, PairsWithAnAwakeProxyAreExactlyTheOverlappingOnes) {
  std::mt19937 rng(58);
  SplitBroadPhase broad(GetParam());
  std::vector<Aabb> boxes;
  std::vector<char> alive, awake;
  for (int i = 0; i < kProxies; ++i) {
    const Aabb box = randomBox(rng);
    const ProxyId id = broad.add(box);
    ASSERT_EQ(id, boxes.size());
    boxes.push_back(box);
    alive.push_back(1);
    awake.push_back(i % 3 == 0);  // a third awake, the rest resting (asleep or static)
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0), step(-0.3, 0.3);
  std::size_t restingPairs = 0;
  for (int u = 0; u < kUpdates; ++u) {
    // Some wake, some fall asleep, a few go and a few come (reusing ids), the awake ones move.
    for (ProxyId id = 0; id < boxes.size(); ++id) {
      if (!alive[id]) continue;
      const double r = unit(rng);
      if (r < 0.02) {
        broad.remove(id);
        alive[id] = 0;
        awake[id] = 0;
        continue;
      }
      if (r < 0.08) awake[id] = !awake[id];
    }
    for (int k = 0; k < 3; ++k) {
      const Aabb box = randomBox(rng);
      const ProxyId id = broad.add(box);
      if (id >= boxes.size()) {
        boxes.resize(id + 1);
        alive.resize(id + 1, 0);
        awake.resize(id + 1, 0);
      }
      ASSERT_FALSE(alive[id]) << "an id handed out twice";
      boxes[id] = box;
      alive[id] = 1;
      awake[id] = unit(rng) < 0.5;
    }
    std::vector<ProxyId> awakeIds;
    for (ProxyId id = 0; id < boxes.size(); ++id) {
      if (!alive[id] || !awake[id]) continue;
      const Vec3 d(step(rng), step(rng), step(rng));
      boxes[id] = {boxes[id].min + d, boxes[id].max + d};
      broad.move(id, boxes[id]);
      awakeIds.push_back(id);
    }
    std::shuffle(awakeIds.begin(), awakeIds.end(), rng);  // any order
    broad.update(awakeIds);
    const std::vector<ProxyPair> expected = bruteForce(boxes, alive, awake);
    ASSERT_EQ(broad.pairs(), expected) << "update " << u;
    for (const ProxyPair& p : expected) restingPairs += !awake[p.a] || !awake[p.b];
    // resting(): the resting proxies whose box meets a query box, as brute force finds them.
    const Aabb query = randomBox(rng).inflated(2.0);
    std::vector<ProxyId> found;
    broad.resting(query, found);
    std::sort(found.begin(), found.end());
    std::vector<ProxyId> near;
    for (ProxyId id = 0; id < boxes.size(); ++id) {
      if (alive[id] && !awake[id] && boxes[id].overlaps(query)) near.push_back(id);
    }
    ASSERT_EQ(found, near) << "update " << u;
  }
  EXPECT_GT(restingPairs, 100u) << "the scene pairs awake with resting proxies";
}

TEST_P(SplitBroadPhaseTest, ACopyGoesOnAlone) {
  SplitBroadPhase broad(GetParam());
  std::vector<ProxyId> all;
  const Vec3 half = Vec3::Constant(0.4);  // [m] a row of boxes 0.5 m apart: each meets its neighbours
  for (int i = 0; i < 50; ++i) all.push_back(broad.add({Vec3(0.5 * i, 0, 0) - half, Vec3(0.5 * i, 0, 0) + half}));
  broad.update(all);
  SplitBroadPhase copy(broad);
  EXPECT_EQ(copy.pairs().size(), 49u);
  EXPECT_EQ(copy.pairs(), broad.pairs());
  broad.update({});  // every proxy rests: no pair
  EXPECT_TRUE(broad.pairs().empty());
  copy.update(all);
  EXPECT_FALSE(copy.pairs().empty());
}

INSTANTIATE_TEST_SUITE_P(Methods, SplitBroadPhaseTest,
                         ::testing::Values(Settings::BroadPhaseMethod::SweepAndPrune, Settings::BroadPhaseMethod::BruteForce));

}  // namespace
}  // namespace rbsim
