// World::destroyBodies (body/body_removal.h): removing a batch leaves the World exactly as
// destroying the same ids one at a time would, on a scene with resting and sleeping contacts,
// joints, springs, scripted forces and pose events: the same bodies at the same indices, the
// same ids valid, the same contacts and joints, and the same trajectory after, bit for bit. A
// stale or repeated id refuses the batch and leaves the World as it was.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../sanitized_build.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

// Columns of boxes resting on the ground and on each other (contacts that turn round when a
// higher-indexed box moves below its partner), with a jointed chain hanging beside them.
constexpr int kColumns = 5;          // per side of the grid of columns
constexpr int kColumnHeight = 3;     // boxes per column
constexpr double kBoxPitch = 0.505;  // [m] between column centres: within the contact margin
constexpr int kChainLinks = 6;
constexpr double kSettleTime = 1.5;  // [s] before the removal: long enough for columns to sleep
constexpr int kStepsAfter = 90;      // steps compared after the removal
constexpr int kSanitizedStepsAfter = 20;  // the same under the sanitizers
// [s] for the edge cases, which ask nothing of the rest: the boxes start touching, so a few steps
// give them contacts, warm starts and touching pairs to remove (90 steps took 16 s sanitized).
constexpr double kEdgeSettleTime = 0.1;

BodyDef batchBox(const std::string& name, const Vec3& position) {
  BodyDef def = shapeBodyDef(Shape::box(Vec3::Constant(0.5)), 1.0, name);
  def.position = position;
  return def;
}

struct BatchScene {
  World world;
  std::vector<BodyId> ids;  // every body, in the order added
};

BatchScene batchScene(Settings::ContactSolverMethod solver, bool sleep, double settleTime = kSettleTime) {
  Settings s;
  s.solver = solver;
  s.allowSleep = sleep;
  BatchScene scene{World(s), {}};
  World& w = scene.world;
  w.addPlane(Plane{});
  for (int i = 0; i < kColumns; ++i) {
    for (int j = 0; j < kColumns; ++j) {
      for (int k = 0; k < kColumnHeight; ++k) {
        const Vec3 at(i * kBoxPitch, 0.25 + 0.5 * k, j * kBoxPitch);
        scene.ids.push_back(w.addBody(batchBox("box_" + std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k), at)));
      }
    }
  }
  // The chain: joints need the soft-step solver; under the others the links fall free.
  const bool joints = solver == Settings::ContactSolverMethod::SoftStep;
  for (int k = 0; k < kChainLinks; ++k) {
    const BodyId link = w.addBody(batchBox("link_" + std::to_string(k), Vec3(5.0 + 0.6 * k, 4.0, 0.0)));
    if (joints) {
      JointDef joint;
      joint.bodyA = link;
      joint.bodyB = k == 0 ? kWorldAnchor : scene.ids.back();
      joint.anchor = Vec3(4.7 + 0.6 * k, 4.0, 0.0);
      w.addJoint(joint);
    }
    scene.ids.push_back(link);
  }
  for (std::size_t k = 0; k < scene.ids.size(); k += 7) {
    Spring spring;
    spring.body = scene.ids[k];
    spring.anchor = w.body(scene.ids[k]).position() + Vec3(0.0, 2.0, 0.0);
    spring.stiffness = 5.0;
    spring.restLength = 2.0;
    addSpring(w, spring);
  }
  for (std::size_t k = 3; k < scene.ids.size(); k += 11) {
    ScriptedForce push;
    push.body = scene.ids[k];
    push.force = Vec3(0.5, 0.0, 0.0);
    push.start = 0.0;
    push.end = 10.0;
    w.addForce(push);
  }
  for (std::size_t k = 5; k < scene.ids.size(); k += 13) {
    PoseEvent kick;
    kick.body = scene.ids[k];
    kick.time = kSettleTime + 0.5;
    kick.velocity = Vec3(0.0, 1.0, 0.0);
    w.addPoseEvent(kick);
  }
  const int settle = static_cast<int>(settleTime / s.timeStep);
  for (int i = 0; i < settle; ++i) w.step();
  return scene;
}

// About 40% of the bodies, drawn by `seed`, in a drawn order.
std::vector<BodyId> drawnBatch(const std::vector<BodyId>& ids, std::uint64_t seed) {
  UniformRandom random(seed);
  std::vector<BodyId> batch;
  for (const BodyId id : ids) {
    if (random.next() < 0.4) batch.push_back(id);
  }
  for (std::size_t i = batch.size(); i > 1; --i) {
    std::swap(batch[i - 1], batch[static_cast<std::size_t>(random.next() * static_cast<double>(i))]);
  }
  return batch;
}

void expectSameWorld(const World& batched, const World& oneByOne, const std::vector<BodyId>& ids) {
  ASSERT_EQ(batched.bodies().size(), oneByOne.bodies().size());
  for (std::size_t i = 0; i < batched.bodies().size(); ++i) {
    EXPECT_EQ(batched.bodies()[i].name(), oneByOne.bodies()[i].name()) << i;
    EXPECT_EQ(batched.bodies()[i].awake(), oneByOne.bodies()[i].awake()) << batched.bodies()[i].name();
  }
  EXPECT_EQ(batched.stateHash(), oneByOne.stateHash());
  for (const BodyId id : ids) {
    ASSERT_EQ(batched.isValid(id), oneByOne.isValid(id));
    if (batched.isValid(id)) {
      EXPECT_EQ(batched.indexOf(id), oneByOne.indexOf(id));
    }
  }
  ASSERT_EQ(batched.contacts().size(), oneByOne.contacts().size());
  for (std::size_t k = 0; k < batched.contacts().size(); ++k) {
    const Contact& x = batched.contacts()[k];
    const Contact& y = oneByOne.contacts()[k];
    EXPECT_TRUE(x.kind == y.kind && x.a == y.a && x.b == y.b && x.part == y.part && x.childA == y.childA &&
                x.childB == y.childB && x.manifold.normal == y.manifold.normal)
        << "contact " << k;
  }
  ASSERT_EQ(batched.joints().size(), oneByOne.joints().size());
  for (std::size_t k = 0; k < batched.joints().size(); ++k) {
    EXPECT_TRUE(batched.joints()[k].def.bodyA == oneByOne.joints()[k].def.bodyA) << "joint " << k;
    EXPECT_TRUE(batched.joints()[k].def.bodyB == oneByOne.joints()[k].def.bodyB) << "joint " << k;
  }
  ASSERT_EQ(springs(batched).size(), springs(oneByOne).size());
  for (std::size_t k = 0; k < springs(batched).size(); ++k) EXPECT_EQ(springs(batched)[k].body, springs(oneByOne)[k].body);
  ASSERT_EQ(scriptedForces(batched).size(), scriptedForces(oneByOne).size());
  for (std::size_t k = 0; k < scriptedForces(batched).size(); ++k) {
    EXPECT_EQ(scriptedForces(batched)[k].body, scriptedForces(oneByOne)[k].body);
  }
}

class BatchRemoval : public testing::TestWithParam<Settings::ContactSolverMethod> {};

TEST_P(BatchRemoval, EqualsDestroyingOneByOneAndSteppingOn) {
  // Under the sanitizers (minutes a run) the comparison steps on for fewer steps, and one drawn
  // batch of the three: the removal and the first steps after it are what reach new code, and
  // every batch reaches the same code (tests/sanitized_build.h).
  const int stepsAfter = test::kSanitizedBuild ? kSanitizedStepsAfter : kStepsAfter;
  const std::vector<std::uint64_t> seeds = test::kSanitizedBuild ? std::vector<std::uint64_t>{1u} : std::vector<std::uint64_t>{1u, 2u, 3u};
  for (const bool sleep : {false, true}) {
    const BatchScene scene = batchScene(GetParam(), sleep);  // settled once, copied for each batch
    for (const std::uint64_t seed : seeds) {
      const std::vector<BodyId> batch = drawnBatch(scene.ids, seed);
      ASSERT_GT(batch.size(), 10u);
      World batched(scene.world), oneByOne(scene.world);
      batched.destroyBodies(batch);
      for (const BodyId id : batch) oneByOne.destroyBody(id);
      SCOPED_TRACE("sleep " + std::to_string(sleep) + ", seed " + std::to_string(seed));
      expectSameWorld(batched, oneByOne, scene.ids);
      for (int i = 0; i < stepsAfter; ++i) {
        batched.step();
        oneByOne.step();
        ASSERT_EQ(batched.stateHash(), oneByOne.stateHash()) << "step " << i << " after the removal";
      }
      expectSameWorld(batched, oneByOne, scene.ids);
      // The freed slots are handed out in the same order.
      EXPECT_EQ(batched.addBody(batchBox("new", Vec3(0, 9, 0))), oneByOne.addBody(batchBox("new", Vec3(0, 9, 0))));
    }
  }
}

// The LCP solver renumbers its warm starts as PGS does (contact_key.h renumberCache); its dense
// solve refuses the scene's island of ~5500 contact points (kMaxLcpRows).
INSTANTIATE_TEST_SUITE_P(Solvers, BatchRemoval,
                         testing::Values(Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs),
                         [](const testing::TestParamInfo<Settings::ContactSolverMethod>& info) {
                           return std::to_string(static_cast<int>(info.param));
                         });

// The whole World, removed at once: nothing is left, every id is stale, and it steps on empty.
TEST(BatchRemovalEdges, EveryBodyAtOnce) {
  BatchScene scene = batchScene(Settings::ContactSolverMethod::SoftStep, false, kEdgeSettleTime);
  ASSERT_FALSE(scene.world.contacts().empty());
  scene.world.destroyBodies(scene.ids);
  EXPECT_TRUE(scene.world.bodies().empty());
  EXPECT_TRUE(scene.world.contacts().empty());
  EXPECT_TRUE(scene.world.joints().empty());
  EXPECT_TRUE(springs(scene.world).empty());
  for (const BodyId id : scene.ids) EXPECT_FALSE(scene.world.isValid(id));
  scene.world.step();
}

TEST(BatchRemovalEdges, AStaleOrRepeatedIdRefusesTheBatchAndChangesNothing) {
  BatchScene scene = batchScene(Settings::ContactSolverMethod::SoftStep, false, kEdgeSettleTime);
  World& w = scene.world;
  ASSERT_FALSE(w.contacts().empty());
  const BodyId gone = scene.ids[4];
  w.destroyBody(gone);
  const std::uint64_t hash = w.stateHash();
  const std::size_t bodies = w.bodies().size(), contacts = w.contacts().size(), joints = w.joints().size();
  EXPECT_THROW(w.destroyBodies({scene.ids[0], gone, scene.ids[9]}), std::invalid_argument);
  EXPECT_THROW(w.destroyBodies({scene.ids[0], scene.ids[9], scene.ids[0]}), std::invalid_argument);
  EXPECT_EQ(w.bodies().size(), bodies);
  EXPECT_EQ(w.contacts().size(), contacts);
  EXPECT_EQ(w.joints().size(), joints);
  EXPECT_EQ(w.stateHash(), hash);
  EXPECT_TRUE(w.isValid(scene.ids[0]));
  EXPECT_TRUE(w.isValid(scene.ids[9]));
  w.destroyBodies({});
  EXPECT_EQ(w.bodies().size(), bodies);
}

}  // namespace
}  // namespace rbsim
