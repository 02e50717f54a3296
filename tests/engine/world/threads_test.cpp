// Settings::threads (issue 34): a step's loops over bodies, pairs and solver islands run on the
// threads of oneTBB's pool (issue 54), and the result must not depend on how many: the state of every body after a pyramid of
// boxes settles, after a grid of spheres hangs on ball joints, and after a hundred separate stacks
// settle, is bit for bit the same for 1, 2 and 4 threads (4 on a 2-core machine too). The tests
// lower the pool's threshold to kTestMinParallelItems, which each scene's bodies, pairs, points
// and constraints exceed, so every parallel loop runs on threads.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "rbsim/body/shape_body.h"
#include "rbsim/dynamics/solver_islands.h"
#include "rbsim/math/parallel.h"
#include "../../sanitized_build.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim::test {
namespace {

// FNV-1a over the bits of every body's x, q, P and L.
std::uint64_t stateHash(const World& world) {
  std::uint64_t hash = 1469598103934665603ull;
  const auto mix = [&](double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      hash ^= (bits >> (8 * k)) & 0xffu;
      hash *= 1099511628211ull;
    }
  };
  for (const RigidBody& b : world.bodies()) {
    const BodyState& s = b.state();
    for (int k = 0; k < 3; ++k) mix(s.position[k]), mix(s.linearMomentum[k]), mix(s.angularMomentum[k]);
    for (int k = 0; k < 4; ++k) mix(s.orientation.coeffs()[k]);
  }
  return hash;
}

Settings sceneSettings(int threads) {
  Settings s;
  s.timeStep = 1.0 / 60.0;
  s.gravity = Vec3(0.0, -10.0, 0.0);
  s.allowSleep = false;
  s.integrator = Integrator::ExpMap;
  s.threads = threads;
  return s;
}

// Box3D's pyramid layout (shared/benchmarks.c CreateLargePyramid) with `rows` rows of unit cubes.
std::uint64_t pyramidHash(int threads, int rows, int steps) {
  World world(sceneSettings(threads));
  const Material material{0.0, 0.6, 0.6};
  world.addPlane(Plane{}, material);
  for (int i = 0; i < rows; ++i) {
    for (int j = i; j < rows; ++j) {
      BodyDef def = boxDef(Vec3::Ones(), 100.0);
      def.shape = Shape::box(Vec3::Constant(0.5));
      def.material = material;
      def.position = Vec3(0.5 * (i + 1) + (j - i) - 0.5 * rows, 0.5 * (2 * i + 1), 0.0);
      world.addBody(def);
    }
  }
  for (int s = 0; s < steps; ++s) world.step();
  return stateHash(world);
}

// `stacks` separate columns of `height` unit boxes 2 m apart: as many solver islands.
std::uint64_t stacksHash(int threads, int stacks, int height, int steps) {
  World world(sceneSettings(threads));
  const Material material{0.0, 0.6, 0.6};
  world.addPlane(Plane{}, material);
  for (int s = 0; s < stacks; ++s) {
    for (int i = 0; i < height; ++i) {
      BodyDef def = boxDef(Vec3::Ones(), 1.0);
      def.shape = Shape::box(Vec3::Constant(0.5));
      def.material = material;
      // A little off-centre and turned, so each stack has its own motion to keep.
      def.position = Vec3(2.0 * (s % 10) + 0.01 * i, 0.5 + i, 2.0 * (s / 10));
      def.orientation = Quat(Eigen::AngleAxisd(0.02 * ((s + i) % 5), Vec3::UnitY()));
      world.addBody(def);
    }
  }
  for (int s = 0; s < steps; ++s) world.step();
  return stateHash(world);
}

// Box3D's joint grid (shared/benchmarks.c CreateJointGrid): n x n balls, the top row static, each
// ball on ball joints to the ones above and to its left.
std::uint64_t jointGridHash(int threads, int n, int steps) {
  World world(sceneSettings(threads));
  std::vector<std::size_t> index(static_cast<std::size_t>(n * n));
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < n; ++i) {
      BodyDef def = shapeBodyDef(Shape::sphere(0.4), 1000.0 * 4.0 / 3.0 * M_PI * 0.4 * 0.4 * 0.4, "ball");
      def.isStatic = i == 0;
      def.position = Vec3(k, -i, 0.0);
      world.addBody(def);
      index[static_cast<std::size_t>(k * n + i)] = world.bodies().size() - 1;
      JointDef joint;
      joint.bodyA = world.idAt(index[static_cast<std::size_t>(k * n + i)]);
      if (i > 0) {
        joint.bodyB = world.idAt(index[static_cast<std::size_t>(k * n + i - 1)]);
        joint.anchor = Vec3(k, -i + 0.5, 0.0);
        world.addJoint(joint);
      }
      if (k > 0 && i > 0) {
        joint.bodyB = world.idAt(index[static_cast<std::size_t>((k - 1) * n + i)]);
        joint.anchor = Vec3(k - 0.5, -i, 0.0);
        world.addJoint(joint);
      }
    }
  }
  for (int s = 0; s < steps; ++s) world.step();
  return stateHash(world);
}

// Far below the default (kDefaultMinParallelItems), so that these scenes of 600 to 1600 bodies
// hand every loop to the pool.
constexpr std::size_t kTestMinParallelItems = 16;  // [items]

// Under the sanitizers a few steps: each still runs every parallel loop (the sanitized suite's
// time is CI's longest part).
const int kStepScale = test::kSanitizedBuild ? 1 : 3;
// And smaller scenes there, each still far above kTestMinParallelItems bodies, pairs and
// constraints (the normal build runs the full sizes: 820 boxes, 1600 balls, 600 boxes).
const int kPyramidRows = test::kSanitizedBuild ? 20 : 40;
const int kGridSide = test::kSanitizedBuild ? 20 : 40;
const int kStacks = test::kSanitizedBuild ? 30 : 100;

TEST(Threads, APyramidEndsBitForBitTheSameOnOneTwoAndFourThreads) {
  const detail::ScopedMinParallelItems pool(kTestMinParallelItems);
  const std::uint64_t one = pyramidHash(1, kPyramidRows, 10 * kStepScale);
  EXPECT_EQ(pyramidHash(2, kPyramidRows, 10 * kStepScale), one);
  EXPECT_EQ(pyramidHash(4, kPyramidRows, 10 * kStepScale), one);
}

TEST(Threads, AJointGridEndsBitForBitTheSameOnOneTwoAndFourThreads) {
  const detail::ScopedMinParallelItems pool(kTestMinParallelItems);
  const std::uint64_t one = jointGridHash(1, kGridSide, 7 * kStepScale);
  EXPECT_EQ(jointGridHash(2, kGridSide, 7 * kStepScale), one);
  EXPECT_EQ(jointGridHash(4, kGridSide, 7 * kStepScale), one);
}

TEST(Threads, AHundredStacksEndBitForBitTheSameOnOneTwoAndFourThreads) {
  const detail::ScopedMinParallelItems pool(kTestMinParallelItems);
  const std::uint64_t one = stacksHash(1, kStacks, 6, 20 * kStepScale);
  EXPECT_EQ(stacksHash(2, kStacks, 6, 20 * kStepScale), one);
  EXPECT_EQ(stacksHash(4, kStacks, 6, 20 * kStepScale), one);
}

// The hash sees a change: one body nudged by 1e-12 m changes it (the test above cannot pass by
// hashing nothing).
TEST(Threads, TheStateHashSeesTheSmallestChange) {
  World world(sceneSettings(1));
  world.addBody(boxDef(Vec3::Ones(), 1.0));
  const std::uint64_t before = stateHash(world);
  world.body(world.idAt(0)).setPosition(Vec3(1e-12, 0.0, 0.0));
  EXPECT_NE(stateHash(world), before);
}

// Islands: every constraint in exactly one, linked constraints together, the ground (slot 0)
// linking nothing, each island's constraints in the order given, the largest island first.
TEST(Threads, IslandsSplitAtTheGroundAndKeepTheOrderGiven) {
  // Slots 1..9: contacts chain 1-2-3 and 4-5, and every slot 1..6 on the ground; a joint links 7-8,
  // another hangs 9 on the ground.
  const std::vector<std::pair<int, int>> contacts{{1, 2}, {0, 4}, {2, 3}, {0, 1}, {4, 5}, {0, 6}, {3, 0}};
  const std::vector<std::pair<int, int>> joints{{7, 8}, {0, 9}};
  SolverIslands islands;
  islands.build(
      10, contacts.size(), [&](std::size_t i) { return contacts[i].first; }, [&](std::size_t i) { return contacts[i].second; },
      joints.size(), [&](std::size_t i) { return joints[i].first; }, [&](std::size_t i) { return joints[i].second; });
  ASSERT_EQ(islands.count(), 5u);  // {1,2,3}, {4,5}, {6}, {7,8}, {9}
  std::vector<std::vector<std::size_t>> contactsOf(islands.count()), jointsOf(islands.count());
  for (std::size_t k = 0; k < islands.count(); ++k) {
    islands.forContacts(k, [&](std::size_t i) { contactsOf[k].push_back(i); });
    islands.forJoints(k, [&](std::size_t i) { jointsOf[k].push_back(i); });
    EXPECT_EQ(islands.constraints(k), contactsOf[k].size() + jointsOf[k].size());
  }
  EXPECT_EQ(contactsOf[0], (std::vector<std::size_t>{0, 2, 3, 6}));
  EXPECT_EQ(contactsOf[1], (std::vector<std::size_t>{1, 4}));
  EXPECT_EQ(contactsOf[2], (std::vector<std::size_t>{5}));
  EXPECT_EQ(jointsOf[3], (std::vector<std::size_t>{0}));
  EXPECT_EQ(jointsOf[4], (std::vector<std::size_t>{1}));
}

// An exception in any item reaches the caller, once, after every thread is done.
TEST(Threads, AnItemsExceptionReachesTheCaller) {
  const detail::ScopedMinParallelItems pool(kTestMinParallelItems);
  std::vector<int> done(4 * kTestMinParallelItems, 0);
  EXPECT_THROW(parallelFor(done.size(), 4,
                           [&](std::size_t i) {
                             done[i] = 1;
                             if (i == 3 * kTestMinParallelItems) throw std::runtime_error("item failed");
                           }),
               std::runtime_error);
}

}  // namespace
}  // namespace rbsim::test
