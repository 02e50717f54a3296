// The overlay's "restitution below" row (app/run/frame_builder.h): shown when a body bounces,
// with the threshold under which approaches do not, or saying the threshold is off.
#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
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

}  // namespace
}  // namespace rbsim::app
