// A World's copy is a saved state (issue 39, Python's get_state and set_state): stepping the copy
// gives bit for bit what stepping the original gives, on shipped scenes that exercise every part
// of the state (sleeping stacks and their kept contacts, both solvers' warm starts, joints,
// particles with their random streams, soft bodies, the 2D world, fracture, grids, the exact
// integrator's memo); restoring the copy rewinds; the copy goes on alone.
// And World::setSettings: the settings a running World can take, checked as a scene's.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../sanitized_build.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/integrate/integrator.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "test_util.h"

namespace rbsim::test {
namespace {

// Under the sanitizers fewer steps: each still passes the moments that matter for most scenes.
const int kCopySteps = kSanitizedBuild ? 20 : 90;

struct CopyCase {
  const char* label;
  const char* scene;
  std::vector<std::string> overrides;
};

void PrintTo(const CopyCase& c, std::ostream* os) { *os << c.label; }

World sceneWorld(const CopyCase& c) {
  return buildWorld(loadScene(std::string(RBSIM_ASSET_DIR) + "/scenes/" + c.scene, c.overrides));
}

void stepN(World& world, int n) {
  for (int i = 0; i < n; ++i) world.step();
}

class WorldCopy : public ::testing::TestWithParam<CopyCase> {};

TEST_P(WorldCopy, TheCopyGoesOnBitForBitAsTheOriginalAndRestoringItRewinds) {
  World original = sceneWorld(GetParam());
  stepN(original, kCopySteps);
  const World saved(original);  // the saved state
  EXPECT_EQ(saved.stateHash(), original.stateHash());

  stepN(original, kCopySteps);
  const std::uint64_t uninterrupted = original.stateHash();
  const double uninterruptedTime = original.time();
  const std::size_t contacts = original.contacts().size();

  World copy(saved);
  stepN(copy, kCopySteps);
  EXPECT_EQ(copy.stateHash(), uninterrupted);
  EXPECT_EQ(copy.time(), uninterruptedTime);
  EXPECT_EQ(copy.contacts().size(), contacts);

  original = saved;  // rewind the original itself
  EXPECT_EQ(original.stateHash(), saved.stateHash());
  stepN(original, kCopySteps);
  EXPECT_EQ(original.stateHash(), uninterrupted);
}

TEST_P(WorldCopy, TheCopyGoesOnAlone) {
  World original = sceneWorld(GetParam());
  stepN(original, kCopySteps / 2);
  const std::uint64_t before = original.stateHash();
  World copy(original);
  stepN(copy, kCopySteps);
  EXPECT_EQ(original.stateHash(), before);
  EXPECT_NE(copy.stateHash(), before);
}

INSTANTIATE_TEST_SUITE_P(
    ShippedScenes, WorldCopy,
    ::testing::Values(CopyCase{"SleepingStacks", "contact_stacking.json", {}},
                      CopyCase{"PgsStacks", "contact_stacking.json", {"world.solver=\"pgs\""}},
                      CopyCase{"Joints", "assignment2_f_joints.json", {}},
                      CopyCase{"ExactIntegrator", "assignment2_b_velocity.json", {"world.integrator=\"exact\""}},
                      CopyCase{"Particles", "particles_fountain.json", {}}, CopyCase{"SoftBodies", "soft_jelly.json", {}},
                      CopyCase{"World2D", "planar_tumbling.json", {}}, CopyCase{"Fracture", "fracture_wall.json", {}},
                      CopyCase{"Grids", "sdf_pour.json", {}}, CopyCase{"RoundShapes", "round_shapes.json", {}},
                      CopyCase{"CompoundsAndMotions", "machinery_table.json", {}},
                      CopyCase{"SpawnerAndKillVolume", "machinery_table.json",
                               {R"(spawn=[{"name": "rock", "count": 2, "period": 0.5, "region": {"min": [-1, 3, -1], "max": [1, 4, 1]},
                                           "body": {"shape": {"type": "box", "extents": [0.2, 0.2, 0.2]}, "mass": 1}}])",
                                R"(kill_volume={"min": [-1, -1, -1], "max": [1, 5, 1]})"}}),
    [](const ::testing::TestParamInfo<CopyCase>& info) { return std::string(info.param.label); });

// One falling sphere, no contacts: each setting's effect has a closed form.
World fallingSphere(const Settings& settings) {
  World world(settings);
  BodyDef def = shapeBodyDef(Shape::sphere(0.5), 2.0, "ball");
  def.position = Vec3(0.0, 10.0, 0.0);
  world.addBody(def);
  return world;
}

TEST(WorldSettings, ANewTimeStepCountsFromNowAndTimeGoesOn) {
  Settings s;
  s.timeStep = 1.0 / 60.0;
  World world = fallingSphere(s);
  stepN(world, 30);
  s.timeStep = 1.0 / 240.0;
  world.setSettings(s);
  EXPECT_DOUBLE_EQ(world.time(), 0.5);
  stepN(world, 120);
  EXPECT_NEAR(world.time(), 1.0, 1e-12);
  EXPECT_EQ(world.stepCount(), 150u);
}

TEST(WorldSettings, NewGravityActsFromTheNextStep) {
  Settings s;
  World world = fallingSphere(s);
  s.gravity = Vec3(3.0, 0.0, 0.0);
  world.setSettings(s);
  stepN(world, 10);
  const Vec3 v = world.bodies()[0].velocity();
  EXPECT_NEAR(v.x(), 3.0 * 10 * s.timeStep, 1e-12);
  EXPECT_EQ(v.y(), 0.0);
}

TEST(WorldSettings, ANewIntegratorTakesTheNextStep) {
  Settings s;
  s.gravity = Vec3::Zero();
  World world = fallingSphere(s);
  world.body(world.idAt(0)).setAngularVelocity(Vec3(0.3, 2.0, 0.1));
  stepN(world, 5);
  s.integrator = Integrator::Rk4;
  world.setSettings(s);
  const RigidBody& body = world.bodies()[0];
  const BodyState expected = integrate(Integrator::Rk4, body.state(), body.stepInputs(), s.timeStep);
  world.step();
  EXPECT_EQ(world.bodies()[0].state().orientation.coeffs(), expected.orientation.coeffs());
}

TEST(WorldSettings, TheSolverSwitchesAndPgsIsRefusedWithJoints) {
  Settings s;
  World world = fallingSphere(s);
  s.solver = Settings::ContactSolverMethod::Pgs;
  world.setSettings(s);
  EXPECT_EQ(world.settings().solver, Settings::ContactSolverMethod::Pgs);

  Settings soft;
  World jointed = fallingSphere(soft);
  JointDef joint;
  joint.bodyA = jointed.idAt(0);
  joint.anchor = Vec3(0.0, 11.0, 0.0);
  jointed.addJoint(joint);
  soft.solver = Settings::ContactSolverMethod::Pgs;
  EXPECT_THROW(jointed.setSettings(soft), std::invalid_argument);
  EXPECT_EQ(jointed.settings().solver, Settings::ContactSolverMethod::SoftStep);  // unchanged
}

TEST(WorldSettings, BadSettingsAndABroadPhaseChangeAreRefusedAndChangeNothing) {
  Settings s;
  World world = fallingSphere(s);
  Settings bad = s;
  bad.timeStep = -1.0;
  EXPECT_THROW(world.setSettings(bad), std::invalid_argument);
  bad = s;
  bad.substeps = 0;
  EXPECT_THROW(world.setSettings(bad), std::invalid_argument);
  bad = s;
  bad.broadPhase = Settings::BroadPhaseMethod::BruteForce;
  EXPECT_THROW(world.setSettings(bad), std::invalid_argument);
  EXPECT_EQ(world.settings().timeStep, s.timeStep);
  EXPECT_EQ(world.settings().substeps, s.substeps);
}

}  // namespace
}  // namespace rbsim::test
