// collision/broadphase/sweep_and_prune: the pairs must equal BruteForce's exactly, after every
// update, on seeded random scenes (std::mt19937, so a failure reproduces): random sizes, lattice
// scenes full of exactly touching and identical boxes, zero-thickness boxes, statics, coherent
// motion, teleporting, and proxies added and removed between updates. Each update's path
// (incremental or rebuild) is checked too, so both are known to be exercised.
#include <random>

#include <gtest/gtest.h>

#include "broad_phase_test_util.h"

namespace rbsim {
namespace {

using Path = SweepAndPrune::Path;
using test::Lockstep;

// A random box: centre uniform in [0, side]^3 [m], half-sizes uniform in [minHalf, maxHalf] [m].
Aabb randomBox(std::mt19937& rng, double side, double minHalf, double maxHalf) {
  std::uniform_real_distribution<double> pos(0.0, side), half(minHalf, maxHalf);
  Vec3 c(pos(rng), pos(rng), pos(rng)), h(half(rng), half(rng), half(rng));
  return {c - h, c + h};
}

// A box on the integer lattice: corners in {0..cells}, sizes in {0..3} (0 is zero thickness).
// Neighbours share faces, edges and corners with exactly equal coordinates, and many coincide.
Aabb latticeBox(std::mt19937& rng, int cells) {
  std::uniform_int_distribution<int> pos(0, cells), size(0, 3);
  Aabb b;
  for (int k = 0; k < 3; ++k) {
    b.min[k] = pos(rng);
    b.max[k] = b.min[k] + size(rng);
  }
  return b;
}

Aabb shifted(const Aabb& b, const Vec3& d) { return {b.min + d, b.max + d}; }

TEST(SweepAndPrune, RandomScenesOfEverySize) {
  for (int n : {0, 1, 2, 1000}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(testing::Message() << n << " bodies, seed " << seed);
      std::mt19937 rng(seed);
      std::bernoulli_distribution isStatic(0.1);
      Lockstep s;
      // Side chosen so a box overlaps a few others on average at n = 1000.
      for (int i = 0; i < n; ++i) s.add(randomBox(rng, 20.0, 0.2, 1.5), isStatic(rng));
      ASSERT_TRUE(s.update());
      if (n == 1000) {
        EXPECT_GT(s.bf.pairs().size(), 500u) << "the scene should be crowded";
      }
    }
  }
}

TEST(SweepAndPrune, LatticeScenesWithExactTies) {
  for (unsigned seed : {4u, 5u, 6u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    Lockstep s;
    for (int i = 0; i < 600; ++i) s.add(latticeBox(rng, 12), i % 7 == 0);
    // Boxes spanning the scene on one or more axes: nested around many others.
    s.add(test::box(0, 0, 0, 15, 15, 15));
    s.add(test::box(0, 5, 5, 15, 6, 6));
    s.add(test::box(3, 0, 3, 3, 15, 3));
    ASSERT_TRUE(s.update());
  }
}

// Every dynamic proxy takes a small random step each update; in the lattice variant a fifth of
// them step by a whole unit, so endpoints keep landing exactly on each other during the sort.
TEST(SweepAndPrune, CoherentMotionStaysIncrementalAndExact) {
  for (bool lattice : {false, true}) {
    SCOPED_TRACE(lattice ? "lattice steps" : "real steps");
    std::mt19937 rng(7);
    Lockstep s;
    std::vector<Aabb> boxes;
    for (int i = 0; i < 400; ++i) {
      boxes.push_back(lattice ? latticeBox(rng, 14) : randomBox(rng, 15.0, 0.2, 1.0));
      s.add(boxes.back(), i % 10 == 0);
    }
    ASSERT_TRUE(s.update());
    std::uniform_real_distribution<double> step(-0.05, 0.05);  // [m]
    std::uniform_int_distribution<int> axis(0, 2), sign(0, 1);
    std::bernoulli_distribution movesThisStep(0.2);
    std::size_t swaps = 0;
    for (int t = 0; t < 150; ++t) {
      for (ProxyId id : s.alive()) {
        if (s.isStatic(id)) continue;
        Vec3 d(step(rng), step(rng), step(rng));
        if (lattice) {  // a unit step along one axis, for a fifth of the bodies
          if (!movesThisStep(rng)) continue;
          d.setZero();
          d[axis(rng)] = sign(rng) ? 1.0 : -1.0;
        }
        boxes[id] = shifted(boxes[id], d);
        s.move(id, boxes[id]);
      }
      ASSERT_TRUE(s.update()) << "step " << t;
      EXPECT_EQ(s.sap.lastUpdate().path, Path::Incremental) << "step " << t;
      swaps += s.sap.lastUpdate().swaps;
    }
    EXPECT_GT(swaps, 1000u) << "the motion should make the sort swap endpoints";
  }
}

// All proxies jump anywhere each update (the rebuild path), then a few of them (incremental).
TEST(SweepAndPrune, TeleportingBodies) {
  std::mt19937 rng(8);
  Lockstep s;
  for (int i = 0; i < 500; ++i) s.add(randomBox(rng, 16.0, 0.2, 1.2), i % 9 == 0);
  ASSERT_TRUE(s.update());
  for (int t = 0; t < 20; ++t) {
    for (ProxyId id : s.alive()) {
      if (!s.isStatic(id)) s.move(id, randomBox(rng, 16.0, 0.2, 1.2));
    }
    ASSERT_TRUE(s.update()) << "all teleport, step " << t;
    EXPECT_EQ(s.sap.lastUpdate().path, Path::Rebuild);
  }
  std::uniform_int_distribution<std::size_t> pick(0, s.alive().size() - 1);
  for (int t = 0; t < 50; ++t) {
    for (int j = 0; j < 3; ++j) {
      const ProxyId id = s.alive()[pick(rng)];
      s.move(id, randomBox(rng, 16.0, 0.2, 1.2));
    }
    ASSERT_TRUE(s.update()) << "three teleport, step " << t;
    EXPECT_EQ(s.sap.lastUpdate().path, Path::Incremental);
  }
}

// A tight cluster inside a wide scene: the even-spread prediction says few swaps, the cluster
// makes many, and the sort is abandoned for a rebuild once it has cost as much. Still exact.
TEST(SweepAndPrune, MispredictedSortFallsBackToRebuild) {
  std::mt19937 rng(9);
  Lockstep s;
  s.add(test::box(-1e6, -1e6, -1e6, -1e6 + 1, -1e6 + 1, -1e6 + 1));
  s.add(test::box(1e6, 1e6, 1e6, 1e6 + 1, 1e6 + 1, 1e6 + 1));
  for (int i = 0; i < 300; ++i) s.add(randomBox(rng, 1.0, 0.01, 0.05));
  ASSERT_TRUE(s.update());
  int abandoned = 0;
  for (int t = 0; t < 10; ++t) {
    for (ProxyId id : s.alive()) {
      if (id >= 2) s.move(id, randomBox(rng, 1.0, 0.01, 0.05));
    }
    ASSERT_TRUE(s.update()) << "step " << t;
    abandoned += s.sap.lastUpdate().path == Path::IncrementalAbandoned;
  }
  EXPECT_EQ(abandoned, 10);
}

// Random adds, removes and moves between updates, with ids reused, proxies removed and re-added
// before an update, and now and then a large batch of adds (which rebuilds).
TEST(SweepAndPrune, AddAndRemoveBetweenUpdates) {
  std::mt19937 rng(10);
  Lockstep s;
  std::bernoulli_distribution coin(0.5), rarely(0.05);
  std::uniform_int_distribution<int> few(0, 3);
  std::uniform_real_distribution<double> step(-0.2, 0.2);  // [m]
  std::vector<Aabb> boxes(4096);
  auto addOne = [&] {
    const Aabb b = randomBox(rng, 12.0, 0.2, 1.0);
    const ProxyId id = s.add(b, rarely(rng));
    boxes[id] = b;
  };
  for (int i = 0; i < 200; ++i) addOne();
  ASSERT_TRUE(s.update());
  int incrementalWithChanges = 0;
  for (int t = 0; t < 200; ++t) {
    const bool batch = t % 50 == 25;
    const int adds = batch ? 150 : few(rng), removes = batch ? 100 : few(rng);
    for (int i = 0; i < removes && !s.alive().empty(); ++i) {
      std::uniform_int_distribution<std::size_t> pick(0, s.alive().size() - 1);
      s.remove(s.alive()[pick(rng)]);
      if (coin(rng)) addOne();  // likely takes the id just freed
    }
    for (int i = 0; i < adds; ++i) addOne();
    for (ProxyId id : s.alive()) {
      if (s.isStatic(id) || !coin(rng)) continue;
      boxes[id] = shifted(boxes[id], Vec3(step(rng), step(rng), step(rng)));
      s.move(id, boxes[id]);
    }
    ASSERT_TRUE(s.update()) << "step " << t;
    if (batch) {
      EXPECT_EQ(s.sap.lastUpdate().path, Path::Rebuild) << "step " << t;
    }
    incrementalWithChanges += !batch && s.sap.lastUpdate().path == Path::Incremental && adds + removes > 0;
  }
  EXPECT_GT(incrementalWithChanges, 100) << "small changes should be sorted in incrementally";
}

// Many statics (never moved) with dynamics moving among them: static-dynamic pairs come and go,
// static-static pairs never appear although the statics overlap each other.
TEST(SweepAndPrune, StaticsAmongMovingBodies) {
  std::mt19937 rng(11);
  Lockstep s;
  std::vector<Aabb> boxes;
  for (int i = 0; i < 300; ++i) {
    boxes.push_back(randomBox(rng, 10.0, 0.3, 1.5));
    s.add(boxes.back(), i < 200);
  }
  ASSERT_TRUE(s.update());
  std::uniform_real_distribution<double> step(-0.1, 0.1);  // [m]
  std::size_t staticDynamic = 0;
  for (int t = 0; t < 100; ++t) {
    for (ProxyId id = 200; id < 300; ++id) {
      boxes[id] = shifted(boxes[id], Vec3(step(rng), step(rng), step(rng)));
      s.move(id, boxes[id]);
    }
    ASSERT_TRUE(s.update()) << "step " << t;
    for (const ProxyPair& p : s.sap.pairs()) staticDynamic += p.a < 200;
  }
  EXPECT_GT(staticDynamic, 0u);
  // The statics do overlap each other: only the rule keeps those pairs out.
  BruteForce allDynamic;
  for (ProxyId id = 0; id < 200; ++id) allDynamic.add(boxes[id]);
  allDynamic.update();
  EXPECT_GT(allDynamic.pairs().size(), 0u);
}

TEST(SweepAndPrune, ZeroThicknessBoxesMoving) {
  std::mt19937 rng(12);
  Lockstep s;
  std::vector<Aabb> boxes;
  std::uniform_int_distribution<int> flatAxes(0, 7);
  for (int i = 0; i < 400; ++i) {
    Aabb b = randomBox(rng, 8.0, 0.1, 1.0);
    const int mask = flatAxes(rng);  // which axes to flatten: planes, segments, points
    for (int k = 0; k < 3; ++k) {
      if (mask & (1 << k)) b.min[k] = b.max[k] = std::round(b.centre()[k]);
    }
    boxes.push_back(b);
    s.add(b);
  }
  ASSERT_TRUE(s.update());
  std::uniform_int_distribution<int> unit(-1, 1);
  for (int t = 0; t < 60; ++t) {
    for (ProxyId id : s.alive()) {
      boxes[id] = shifted(boxes[id], 0.5 * Vec3(unit(rng), unit(rng), unit(rng)));
      s.move(id, boxes[id]);
    }
    ASSERT_TRUE(s.update()) << "step " << t;
  }
}

// Same calls, same pairs: nothing depends on addresses, hashing or timing.
TEST(SweepAndPrune, Deterministic) {
  auto run = [] {
    std::mt19937 rng(13);
    SweepAndPrune sap;
    std::vector<std::vector<ProxyPair>> history;
    for (int i = 0; i < 300; ++i) sap.add(randomBox(rng, 10.0, 0.2, 1.0));
    for (int t = 0; t < 30; ++t) {
      for (ProxyId id = 0; id < 300; id += 1 + t % 3) sap.move(id, randomBox(rng, 10.0, 0.2, 1.0));
      sap.update();
      history.push_back(sap.pairs());
    }
    return history;
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace rbsim
