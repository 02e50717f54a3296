// The overlay's "restitution below" row (app/run/frame_builder.h): shown when a body bounces,
// with the threshold under which approaches do not, or saying the threshold is off. The
// "vs exact spin" row: the error while a body flies free, else the one reason it is not compared.
#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/free_flight_error.h"
#include "run/frame_builder.h"

namespace rbsim::app {
namespace {

World ballWorld(double restitution, double threshold) {
  Settings s;
  s.restitutionThreshold = threshold;
  World world(s);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.1), 1.0, "ball");
  ball.material.restitution = restitution;
  world.addBody(ball);
  return world;
}

TEST(OverlayRows, TheRestitutionThresholdShowsWhenABodyBounces) {
  EXPECT_EQ(restitutionThresholdRow(ballWorld(0.0, 0.5)), "");
  EXPECT_EQ(restitutionThresholdRow(ballWorld(0.7, 0.5)), "0.5 m/s approach: none");
  EXPECT_EQ(restitutionThresholdRow(ballWorld(0.7, 0.0)), "off: every approach bounces (seed 000's law)");
}

TEST(OverlayRows, TheFrameCarriesTheRow) {
  const World world = ballWorld(1.0, 0.25);
  const render::FrameData frame = buildFrame(world, Scene{}, "", /*selectedBodyRows=*/false);
  bool found = false;
  for (const auto& row : frame.overlay.rows) found = found || (row.label == "restitution below" && row.value == "0.25 m/s approach: none");
  EXPECT_TRUE(found);
}


// A spinning box flies free, then lands on the ground (a torque each step it touches), then
// sleeps; a static box is never compared.
TEST(OverlayRows, TheSpinRowGivesTheErrorOrTheOneReasonItIsNotCompared) {
  Settings s;
  s.timeStep = 1.0 / 60.0;
  World world(s);
  world.addPlane(Plane{});
  BodyDef box = shapeBodyDef(Shape::box(Vec3(0.2, 0.1, 0.3)), 1.0, "box");
  box.position = Vec3(0.0, 0.6, 0.0);
  box.angularVelocity = Vec3(0.5, 3.0, 0.2);
  const BodyId id = world.addBody(box);
  BodyDef wall = shapeBodyDef(Shape::box(Vec3(0.1, 0.1, 0.1)), 1.0, "wall");
  wall.isStatic = true;
  wall.position = Vec3(5.0, 0.1, 0.0);
  const BodyId wallId = world.addBody(wall);
  FreeFlightError error(id);
  FreeFlightError wallError(wallId);
  error.observe(world);
  for (int i = 0; i < 10; ++i) {  // 1/6 s of free fall from 0.6 m: still in the air
    world.step();
    error.observe(world);
  }
  EXPECT_NE(freeFlightRow(error, world).find(" rad, dE/E "), std::string::npos) << freeFlightRow(error, world);
  EXPECT_EQ(freeFlightRow(wallError, world), "not compared (static)");
  bool torqued = false;
  for (int i = 0; i < 600 && world.body(id).awake(); ++i) {
    world.step();
    error.observe(world);
    torqued = torqued || freeFlightRow(error, world) == "not compared (torqued this step)";
  }
  EXPECT_TRUE(torqued);
  ASSERT_FALSE(world.body(id).awake());
  EXPECT_EQ(freeFlightRow(error, world), "not compared (asleep)");
}

}  // namespace
}  // namespace rbsim::app
