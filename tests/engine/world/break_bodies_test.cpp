// World stage BreakBodies (seed 000 "Fracture"): a breakable body hit hard enough becomes its
// pieces within the step, the system's momentum unchanged; hit gently, it stays whole.
#include <gtest/gtest.h>

#include "rbsim/fracture/fracture.h"
#include "fracture/pieces.h"
#include "test_util.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::boxDef;

constexpr double kBreakDt = 1.0 / 240.0;         // [s]
constexpr double kThreshold = 2.0;          // breaking impulse of the target [N s]
constexpr double kMomentumTolerance = 1e-12;  // relative

// A 1 kg projectile flying at `speed` along +x into a resting 3 kg breakable slab, no gravity.
World collision(double speed) {
  Settings settings;
  settings.gravity = Vec3::Zero();
  settings.timeStep = kBreakDt;
  settings.allowSleep = false;
  World world(settings);
  BodyDef slab = boxDef(Vec3(0.2, 1.0, 1.0), 3.0, "slab");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = kThreshold;
  for (Mesh& piece : voronoiPieces(*slab.mesh, sitesInside(*slab.mesh, 10, 1))) {
    pattern->pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));
  }
  slab.fracture = pattern;
  world.addBody(slab);
  BodyDef projectile = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "projectile");
  projectile.position = Vec3(-0.5, 0.1, 0.05);
  projectile.velocity = Vec3(speed, 0.0, 0.0);
  world.addBody(projectile);
  return world;
}

Vec3 totalMomentum(const World& world) {
  Vec3 p = Vec3::Zero();
  for (const RigidBody& b : world.bodies()) p += b.state().linearMomentum;
  return p;
}

TEST(BreakBodies, AHardHitShattersTheSlabAndKeepsMomentum) {
  World world = collision(6.0);  // m dv up to 2 x 6 N s, well above the threshold
  const Vec3 before = totalMomentum(world);
  for (int s = 0; s < 120 && fractureEvents(world).empty(); ++s) world.step();
  ASSERT_EQ(fractureEvents(world).size(), 1u);
  const FractureEvent& event = fractureEvents(world).front();
  EXPECT_EQ(world.indexOf(event.body), 0u);
  ASSERT_EQ(event.added.size(), 9u);
  for (std::size_t k = 0; k < event.added.size(); ++k) EXPECT_EQ(world.indexOf(event.added[k]), 2 + k);
  EXPECT_GT(event.impulse, kThreshold);
  ASSERT_EQ(world.bodies().size(), 11u);
  double mass = world.bodies()[0].mass();
  for (std::size_t i = 2; i < world.bodies().size(); ++i) mass += world.bodies()[i].mass();
  EXPECT_NEAR(mass, 3.0, 1e-12);
  EXPECT_LT((totalMomentum(world) - before).norm(), kMomentumTolerance * before.norm());
  // The pieces fly on and collide with each other and the projectile; momentum stays.
  for (int s = 0; s < 240; ++s) world.step();
  EXPECT_LT((totalMomentum(world) - before).norm(), kMomentumTolerance * before.norm());
  EXPECT_GT(world.stageStats(Stage::BreakBodies).runs, 0u);
}

TEST(BreakBodies, AGentleTouchLeavesTheSlabWhole) {
  World world = collision(0.5);  // at most 2 x 0.5 N s, below the threshold
  for (int s = 0; s < 480; ++s) world.step();
  EXPECT_TRUE(fractureEvents(world).empty());
  EXPECT_EQ(world.bodies().size(), 2u);
  EXPECT_GT(world.bodies()[0].velocity().x(), 0.0) << "the slab was hit";
}

TEST(BreakBodies, PatternsThatDoNotFitTheBodyAreRejected) {
  World world{Settings{}};
  BodyDef slab = boxDef(Vec3(0.2, 1.0, 1.0), 3.0, "slab");
  auto pattern = std::make_shared<FracturePattern>();
  pattern->impulseThreshold = kThreshold;
  for (Mesh& piece : cutByPlanes(makeBox(Vec3(0.2, 1.0, 2.0)), {{Vec3::UnitY(), 0.0}})) {
    pattern->pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));  // twice the volume
  }
  slab.fracture = pattern;
  try {
    world.addBody(slab);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("body 'slab': fracture"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbsim
