// "particles" blocks of scene files: every key reaches the definition, and bad values are refused
// with the file, the JSON path and what was expected.
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rbsim/world/systems.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"

namespace rbsim {
namespace {

const char* kScene = R"({
  "world": {"dt": 0.005, "duration": 0.5},
  "bodies": [{"name": "crate", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1, "static": true}],
  "planes": [{"normal": [0, 1, 0]}],
  "particles": [
    {"name": "fire", "seed": 3, "capacity": 500, "integrator": "explicit-euler", "substeps": 2,
     "gravity_scale": -0.4, "drag_linear": 0.01, "drag_quadratic": 0.002,
     "wind": {"velocity": [1, 0, 0], "turbulence": 0.5, "scale": 0.7, "frequency": 2},
     "attractors": [{"position": [0, 3, 0], "strength": -2, "softening": 0.3}],
     "collision": {"restitution": 0.2, "friction": 0.4, "radius": 0.01, "bodies": false},
     "emitters": [{"type": "mesh", "body": "crate", "rate": 300, "speed": [0.1, 0.4], "lifetime": [0.5, 1.0],
                   "mass": 0.002, "size": [0.05, 0.1], "color": [1, 0.5, 0.1], "color_jitter": 0.1}],
     "look": {"blend": "additive", "color_end": [0.3, 0, 0], "alpha_start": 0.9, "alpha_end": 0, "size_end_scale": 0.3}},
    {"name": "sheet", "cloth": {"origin": [-1, 2, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "resolution": [6, 5],
                                "mass": 0.2, "stiffness": 50, "pinned": [[0, 0], [5, 0]]}},
    {"name": "birds", "flock": {"radius": 2, "max_speed": 3, "min_speed": 1},
     "emitters": [{"type": "box", "half_extents": [1, 1, 1], "rate": 0, "burst": 40}]}
  ]
})";

Scene parseParticles(const std::string& text) { return parseScene(nlohmann::json::parse(text), "test.json", "."); }

TEST(ParticleScene, EveryKeyReachesTheDefinition) {
  const Scene scene = parseParticles(kScene);
  ASSERT_EQ(scene.particleSystems.size(), 3u);
  const ParticleSystemDef& fire = scene.particleSystems[0];
  EXPECT_EQ(fire.name, "fire");
  EXPECT_EQ(fire.seed, 3u);
  EXPECT_EQ(fire.capacity, 500u);
  EXPECT_EQ(fire.integrator, ParticleIntegrator::ExplicitEuler);
  EXPECT_EQ(fire.substeps, 2);
  EXPECT_EQ(fire.gravityScale, -0.4);
  EXPECT_EQ(fire.dragQuadratic, 0.002);
  EXPECT_EQ(fire.wind.scale, 0.7);
  EXPECT_EQ(fire.attractors.at(0).strength, -2.0);
  EXPECT_FALSE(fire.collision.bodies);
  EXPECT_EQ(fire.collision.radius, 0.01);
  const EmitterDef& e = fire.emitters.at(0);
  EXPECT_EQ(e.shape, EmitterShape::MeshSurface);
  EXPECT_EQ(e.body, 0u);
  EXPECT_EQ(e.lifetimeMax, 1.0);
  EXPECT_EQ(e.massMin, 0.002);
  EXPECT_EQ(e.massMax, 0.002);
  EXPECT_EQ(scene.particleLooks[0].blend, ParticleLook::Blend::Additive);
  EXPECT_EQ(scene.particleLooks[0].sizeEndScale, 0.3);
  const ClothDef& cloth = scene.particleSystems[1].cloth;
  EXPECT_TRUE(cloth.enabled);
  EXPECT_EQ(cloth.nu, 6);
  EXPECT_EQ(cloth.pinned.size(), 2u);
  EXPECT_TRUE(scene.particleSystems[2].flock.enabled);
  EXPECT_EQ(scene.particleSystems[2].emitters.at(0).burst, 40u);

  World world = buildWorld(scene);
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_GT(particleSystems(world)[0].particles().count(), 50u);
  EXPECT_EQ(particleSystems(world)[1].particles().count(), 30u);
  EXPECT_EQ(particleSystems(world)[2].particles().count(), 40u);
}

TEST(ParticleScene, WorldParticleIntegratorIsTheDefaultASystemMayOverride) {
  const Scene scene = parseParticles(R"({"world": {"particle_integrator": "explicit-euler"},
    "particles": [{"emitters": [{"type": "point"}]},
                  {"integrator": "semi-implicit-euler", "emitters": [{"type": "point"}]}]})");
  EXPECT_EQ(scene.particleSystems[0].integrator, ParticleIntegrator::ExplicitEuler);
  EXPECT_EQ(scene.particleSystems[1].integrator, ParticleIntegrator::SemiImplicitEuler);
}

TEST(ParticleScene, TheSceneFormatExampleParsesAndRuns) {
  // The "particles" example of docs/scene-format.md, "Particle systems" (README.md's until issue 38),
  // from its "particles" key to the end of the code block.
  std::ifstream in(std::string(RBSIM_TEST_DATA_DIR) + "/../../../docs/scene-format.md");
  ASSERT_TRUE(in) << "docs/scene-format.md not found";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t first = doc.find("\"particles\": [ {");
  ASSERT_NE(first, std::string::npos);
  const std::size_t last = doc.find("```", first);
  const Scene scene = parseParticles("{" + doc.substr(first, last - first) + ", \"world\": {\"duration\": 0.1}}");
  ASSERT_EQ(scene.particleSystems.size(), 1u);
  World world = buildWorld(scene);
  for (int i = 0; i < 24; ++i) world.step();
  EXPECT_GT(particleSystems(world)[0].particles().count(), 0u);
}

TEST(ParticleScene, AParticleOnlySceneNeedsNoBodies) {
  const Scene scene = parseParticles(R"({"particles": [{"emitters": [{"type": "point"}]}]})");
  EXPECT_TRUE(scene.bodies.empty());
  EXPECT_EQ(scene.particleSystems.size(), 1u);
}

void expectRefused(const std::string& text, const std::string& field, const std::string& fragment) {
  try {
    parseParticles(text);
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.problem().find(fragment), std::string::npos) << e.what();
  }
}

TEST(ParticleScene, BadValuesAreRefusedNamingTheField) {
  expectRefused(R"({"particles": [{"emitters": [{"type": "cone"}]}]})", "particles[0].emitters[0].type", "\"disc\"");
  expectRefused(R"({"particles": [{"emitters": [{"type": "point", "lifetime": [2, 1]}]}]})",
                "particles[0].emitters[0].lifetime", "low <= high");
  expectRefused(R"({"particles": [{"emitters": [{"type": "mesh", "body": "ghost"}]}]})",
                "particles[0].emitters[0].body", "ghost");
  expectRefused(R"({"particles": [{"integrator": "rk4", "emitters": [{"type": "point"}]}]})", "particles[0].integrator",
                "semi-implicit-euler");
  expectRefused(R"({"particles": [{"drag_linear": -1, "emitters": [{"type": "point"}]}]})", "particles[0].drag_linear",
                ">= 0");
  expectRefused(R"({"particles": [{"name": "x"}]})", "particles[0].emitters", "emitter or a cloth");
  expectRefused(R"({"particles": [{"cloth": {"resolution": [1, 4]}}]})", "particles[0].cloth.resolution", "[2, 1000]");
  expectRefused(R"({"particles": [{"emiters": []}]})", "particles[0].emiters", "did you mean \"emitters\"");
  expectRefused(R"({"particles": [{"emitters": [{"type": "point"}], "look": {"blend": "screen"}}]})",
                "particles[0].look.blend", "additive");
}

}  // namespace
}  // namespace rbsim
