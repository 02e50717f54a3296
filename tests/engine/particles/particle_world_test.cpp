// Particles in the World: stepped by the StepSystems stage (the step hook) only when there are any, and never
// changing a rigid body (the coupling is one-way).
#include <memory>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "particle_test_util.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/systems.h"
#include "rbsim/scene/scene.h"

namespace rbsim {
namespace {

using test::stepN;

World boxes(bool withParticles) {
  Settings settings;
  World world(settings);
  world.addPlane(Plane{});
  for (int i = 0; i < 3; ++i) {
    BodyDef box;
    box.name = "box" + std::to_string(i);
    box.mesh = std::make_shared<Mesh>(makeBox(Vec3(0.5, 0.5, 0.5)));
    box.position = Vec3(0.6 * i, 1.0 + i, 0.0);
    box.angularVelocity = Vec3(1.0, 2.0, 0.5 * i);
    world.addBody(box);
  }
  if (withParticles) {
    ParticleSystemDef def;
    EmitterDef e;
    e.position = Vec3(0.5, 4.0, 0.0);
    e.direction = -Vec3::UnitY();
    e.rate = 2000.0;
    e.lifetimeMin = e.lifetimeMax = 1.0;
    def.emitters.push_back(e);
    addParticleSystem(world, def);
  }
  return world;
}

TEST(ParticleWorld, TheStageIsSkippedWithoutParticles) {
  World world = boxes(false);
  stepN(world, 50);
  EXPECT_EQ(world.stageStats(Stage::StepSystems).runs, 0u);
  EXPECT_EQ(world.stageStats(Stage::StepSystems).skipped, 50u);
  EXPECT_STREQ(stageName(Stage::StepSystems), "step-systems");
}

TEST(ParticleWorld, ParticlesNeverChangeTheRigidBodies) {
  World plain = boxes(false);
  World sprayed = boxes(true);
  stepN(plain, 480);
  stepN(sprayed, 480);
  EXPECT_EQ(sprayed.stageStats(Stage::StepSystems).runs, 480u);
  EXPECT_GT(particleSystems(sprayed)[0].particles().count(), 1000u);
  for (std::size_t b = 0; b < plain.bodies().size(); ++b) {
    const BodyState& a = plain.bodies()[b].state();
    const BodyState& c = sprayed.bodies()[b].state();
    EXPECT_EQ(a.position, c.position);
    EXPECT_EQ(a.orientation.coeffs(), c.orientation.coeffs());
    EXPECT_EQ(a.linearMomentum, c.linearMomentum);
    EXPECT_EQ(a.angularMomentum, c.angularMomentum);
  }
  EXPECT_NE(plain.stateHash(), sprayed.stateHash()) << "the particles are part of the state";
}

TEST(ParticleWorld, ABadDefinitionIsRefusedNamingTheField) {
  World world = boxes(false);
  ParticleSystemDef def;
  def.emitters.push_back(EmitterDef{});
  def.emitters[0].shape = EmitterShape::MeshSurface;
  def.emitters[0].body = 7;
  try {
    addParticleSystem(world, def);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("emitters[0].body"), std::string::npos) << e.what();
  }
}

// A wall that a falling block shatters (planes cut it in four), smoking from its surface: the
// emitter kept the wall's mesh, and the pieces that take over the wall's index have other
// triangles. Sampling them through the old area table read past their storage (SIGSEGV).
constexpr const char* kSmokingWall = R"({
  "world": {"dt": 0.005, "gravity": [0, -9.81, 0], "inertia": "exact"},
  "planes": [{"normal": [0, 1, 0]}],
  "bodies": [
    {"name": "wall", "shape": {"type": "box", "extents": [2, 1, 0.2]}, "mass": 40, "position": [0, 0.5, 0],
     "fracture": {"threshold": 5, "planes": [{"normal": [1, 0, 0], "point": [0, 0, 0]},
                                             {"normal": [0, 1, 0], "point": [0, 0, 0]}]}},
    {"name": "block", "shape": {"type": "box", "extents": [0.4, 0.4, 0.4]}, "mass": 30, "position": [0, 1.6, 0],
     "velocity": [0, -8, 0]}],
  "particles": [{"name": "smoke", "capacity": 4000,
                 "emitters": [{"type": "mesh", "body": "wall", "rate": 20000, "lifetime": 0.5}]}]
})";

TEST(ParticleWorld, AMeshEmitterStopsWhenItsBodyBreaks) {
  const Scene scene = parseScene(nlohmann::json::parse(kSmokingWall), "wall.json", ".");
  World world = buildWorld(scene);
  std::uint64_t emittedAtBreak = 0;
  for (int s = 0; s < 200 && fractureEvents(world).empty(); ++s) world.step();
  ASSERT_EQ(fractureEvents(world).size(), 1u) << "the block must break the wall";
  emittedAtBreak = particleSystems(world)[0].emitted();
  EXPECT_GT(emittedAtBreak, 0u) << "the intact wall smoked";
  EXPECT_NE(world.bodies()[0].mesh().triangles.size(), scene.bodies[0].mesh->triangles.size());
  for (int s = 0; s < 100; ++s) world.step();  // the pieces fall and tumble
  EXPECT_EQ(particleSystems(world)[0].emitted(), emittedAtBreak)
      << "the wall's surface is gone: its emitter emits nothing from the pieces";
  EXPECT_EQ(particleSystems(world)[0].lost(), 0u);
}

}  // namespace
}  // namespace rbsim
