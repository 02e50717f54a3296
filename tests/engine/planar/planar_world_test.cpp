// planar/planar_world: 2D boxes on the ground: a dropped box comes to rest on its face without
// sinking, a stack of five stands, a bouncing box never rises above its last apex, and a box
// sliding on the ground stops at v0^2 / (2 mu_k g).
#include "rbsim/planar/planar_world.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rbsim {
namespace {

std::vector<Vec2> square(double size) {
  const double h = 0.5 * size;
  return {Vec2(-h, -h), Vec2(h, -h), Vec2(h, h), Vec2(-h, h)};
}

PlanarWorld groundWorld(const Material& ground = {}) {
  PlanarWorld world;
  world.addLine(PlanarLine{Vec2::UnitY(), 0.0, ground});
  return world;
}

TEST(PlanarWorld, DroppedTiltedBoxComesToRestOnAFace) {
  PlanarWorld world = groundWorld();
  PlanarBody box("box", square(1.0), 1.0);
  box.state().position = Vec2(0.0, 2.0);
  box.state().angle = 0.4;
  world.addBody(box);
  double lowest = 1.0;
  for (int step = 0; step < 240 * 5; ++step) {
    world.step();
    for (std::size_t i = 0; i < 4; ++i) lowest = std::min(lowest, world.bodies()[0].corner(i).y());
  }
  const PlanarBody& b = world.bodies()[0];
  EXPECT_GT(lowest, -world.settings().contactSlop - 0.01) << "never sinks far into the ground";
  EXPECT_NEAR(b.state().position.y(), 0.5, world.settings().contactSlop + 1e-3);
  EXPECT_NEAR(std::remainder(b.state().angle, M_PI / 2.0), 0.0, 1e-2) << "lies on a face";
  EXPECT_LT(b.velocity().norm() + std::abs(b.angularVelocity()), 1e-3);
}

TEST(PlanarWorld, StackOfFiveStands) {
  PlanarWorld world = groundWorld();
  for (int i = 0; i < 5; ++i) {
    PlanarBody box("box" + std::to_string(i), square(1.0), 1.0);
    box.state().position = Vec2(0.0, 0.5 + i * 1.0);
    world.addBody(box);
  }
  for (int step = 0; step < 240 * 10; ++step) world.step();
  const PlanarBody& top = world.bodies()[4];
  EXPECT_NEAR(top.state().position.x(), 0.0, 0.01);
  EXPECT_NEAR(top.state().position.y(), 4.5, 0.05);
  EXPECT_LT(std::abs(top.state().angle), 0.01);
}

TEST(PlanarWorld, BouncingBoxNeverRisesAboveItsLastApex) {
  Material bouncy;
  bouncy.restitution = 0.6;
  PlanarWorld world = groundWorld(bouncy);
  PlanarBody box("box", square(0.5), 1.0, bouncy);
  box.state().position = Vec2(0.0, 2.0);
  world.addBody(box);
  double apex = 2.0, previous = 0.0;
  int bounces = 0;
  for (int step = 0; step < 240 * 4; ++step) {
    world.step();
    const double v = world.bodies()[0].velocity().y(), y = world.bodies()[0].state().position.y();
    if (previous > 0.0 && v <= 0.0) {  // an apex
      EXPECT_LE(y, apex + 1e-9);
      apex = y;
      ++bounces;
    }
    previous = v;
  }
  EXPECT_GE(bounces, 2);
}

TEST(PlanarWorld, SlidingBoxStopsAtTheKineticDistance) {
  Material ground;
  ground.staticFriction = 0.5;
  ground.kineticFriction = 0.5;
  PlanarWorld world = groundWorld(ground);
  PlanarBody box("box", square(0.5), 1.0, ground);
  box.state().position = Vec2(0.0, 0.25);
  box.state().linearMomentum = Vec2(3.0, 0.0);
  world.addBody(box);
  for (int step = 0; step < 240 * 2; ++step) world.step();
  const double expected = 3.0 * 3.0 / (2.0 * 0.5 * 9.81);
  EXPECT_NEAR(world.bodies()[0].state().position.x(), expected, 0.02 * expected);
  EXPECT_LT(world.bodies()[0].velocity().norm(), 1e-4);
}

}  // namespace
}  // namespace rbsim
