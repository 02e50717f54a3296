// app/render/body_colors.h (issue 58): the engine keeps no colour; the app finds a body's by its
// name in the scene's colours, for the bodies a scene lists, the copies its spawners make while
// the World steps and the pieces its bodies break into, as RigidBody::color gave them before.
#include <string>

#include <gtest/gtest.h>

#include "export/gltf_track.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "render/body_colors.h"

namespace rbsim::app {
namespace {

using nlohmann::json;

const Vec3 kCrate(0.1, 0.2, 0.3), kRain(0.9, 0.1, 0.1);

// A breakable crate thrown at the ground, a spawner of red balls and a body of no colour.
Scene colouredScene() {
  const json document = {
      {"world", {{"dt", 1.0 / 240.0}, {"duration", 0.3}}},
      {"planes", {{{"normal", {0, 1, 0}}}}},
      {"bodies",
       {{{"name", "crate"}, {"shape", {{"type", "box"}, {"extents", {1, 1, 1}}}}, {"density", 100},
         {"position", {0, 0.55, 0}}, {"velocity", {0, -20, 0}}, {"color", {0.1, 0.2, 0.3}},
         {"fracture", {{"threshold", 1}, {"pieces", 4}}}},
        {{"name", "plain"}, {"shape", {{"type", "sphere"}, {"radius", 0.2}}}, {"density", 100}, {"position", {-5, 0.2, 0}}}}},
      {"spawn",
       {{{"name", "rain"}, {"period", 0.05}, {"count", 1},
         {"body", {{"shape", {{"type", "sphere"}, {"radius", 0.1}}}, {"density", 100}, {"color", {0.9, 0.1, 0.1}}}},
         {"region", {{"min", {5, 5, 5}}, {"max", {6, 6, 6}}}}}}}};
  return parseScene(document, "colours.json", ".");
}

TEST(BodyColors, TheSceneFilesColoursByBodyAndBySpawner) {
  const Scene scene = colouredScene();
  EXPECT_EQ(scene.colors.byBody.size(), 1u) << "plain gave none";
  EXPECT_EQ(scene.colors.byBody.at("crate"), kCrate);
  EXPECT_EQ(scene.colors.bySpawner.at("rain"), kRain);
  EXPECT_EQ(bodyColor(scene.colors, "crate"), kCrate);
  EXPECT_EQ(bodyColor(scene.colors, "crate/3"), kCrate) << "a piece";
  EXPECT_EQ(bodyColor(scene.colors, "crate/3/0"), kCrate) << "a piece of a piece";
  EXPECT_EQ(bodyColor(scene.colors, "rain_12"), kRain) << "a spawned copy";
  EXPECT_EQ(bodyColor(scene.colors, "rain_12/1"), kRain) << "a spawned copy's piece";
  EXPECT_EQ(bodyColor(scene.colors, "plain"), kDefaultBodyColor);
  EXPECT_EQ(bodyColor(scene.colors, "rain_x"), kDefaultBodyColor) << "not a name a spawner makes";
  EXPECT_EQ(bodyColor(scene.colors, "rain"), kDefaultBodyColor);
  EXPECT_EQ(bodyColor(scene.colors, "crate/x"), kDefaultBodyColor) << "not a name a fracture makes";
  EXPECT_EQ(bodyColor(scene.colors, "ragdoll_head"), kDefaultBodyColor);
}

TEST(BodyColors, SpawnedCopiesAndPiecesAreDrawnAsWhatTheyCameFrom) {
  const Scene scene = colouredScene();
  World world = buildWorld(scene);
  for (std::uint64_t s = 0; s < scene.stepCount(); ++s) world.step();
  GltfTrack track(scene.colors);
  track.sample(world);
  int pieces = 0, copies = 0;
  ASSERT_EQ(track.bodies().size(), world.bodies().size());
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const std::string& name = world.bodies()[i].name();
    const Vec3 expected = name.rfind("crate/", 0) == 0 ? kCrate : name.rfind("rain_", 0) == 0 ? kRain : kDefaultBodyColor;
    pieces += name.rfind("crate/", 0) == 0 ? 1 : 0;
    copies += name.rfind("rain_", 0) == 0 ? 1 : 0;
    EXPECT_EQ(bodyColor(scene.colors, name), expected) << name;
    EXPECT_EQ(track.bodies()[i].color, expected) << name << " in the glTF track";
  }
  EXPECT_GE(pieces, 2) << "the crate broke";
  EXPECT_GE(copies, 5) << "the spawner made a copy every 0.05 s";
}

}  // namespace
}  // namespace rbsim::app
