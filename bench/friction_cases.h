#pragma once
// The friction and restitution cases of issue 25, shared by tests/engine/world/friction_model_test.cpp
// (which asserts the analytic values) and bench/friction_models.cpp (which prints them for REPORT
// section 5): a box sliding to a stop, a box on an incline, a body dropped onto the ground.
#include <algorithm>
#include <cmath>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/world.h"

namespace rbsim::bench {

inline constexpr double kFrictionG = 9.81;         // |g| [m/s^2], Settings' default
inline constexpr double kCaseStaticFriction = 0.6;   // mu_s [1]
inline constexpr double kCaseKineticFriction = 0.5;  // mu_k [1]; the friction angle is atan(mu_s) = 30.96 deg

// The solver and friction asked for at `dt`, sleep off (the figures are the solver's, not
// sleeping's). PGS integrates before it solves: its friction is measured with the forward-Euler
// drift it was tuned with (docs/integrators.md), as in its other suites; the exact integrator's
// drift of g dt^2 / 2 more a step, pushed back out, creeps down an incline (35 cm in 10 s at 25
// degrees, 1/60 s). Bounces are measured with the default integrator (restitutionSettings).
inline Settings frictionCaseSettings(Settings::ContactSolverMethod solver, Settings::FrictionModel friction, double dt) {
  Settings s;
  s.timeStep = dt;
  s.solver = solver;
  s.friction = friction;
  s.allowSleep = false;
  if (solver == Settings::ContactSolverMethod::Pgs) s.integrator = Integrator::ExpMap;
  return s;
}

// Seed 000's restitution law at every speed: world.restitution_threshold = 0.
inline Settings restitutionSettings(Settings::ContactSolverMethod solver, double dt) {
  Settings s;
  s.timeStep = dt;
  s.solver = solver;
  s.allowSleep = false;
  s.restitutionThreshold = 0.0;
  return s;
}

inline Material caseMaterial(double restitution = 0.0) {
  Material m;
  m.restitution = restitution;
  m.staticFriction = kCaseStaticFriction;
  m.kineticFriction = kCaseKineticFriction;
  return m;
}

// A 0.4 x 0.2 x 0.4 m box of 1 kg resting on `normal`'s plane through the origin, tilted with it.
inline BodyDef caseBox(const Vec3& normal, const Material& material) {
  BodyDef box = shapeBodyDef(Shape::box(Vec3(0.2, 0.1, 0.2)), 1.0, "box");
  box.position = 0.1 * normal;
  box.orientation = Quat::FromTwoVectors(Vec3::UnitY(), normal);
  box.material = material;
  return box;
}

struct SlideResult {
  double distance = 0.0;  // [m] travelled until it stopped
  double stopTime = 0.0;  // [s]
};

// The box slid along x at v0 on the ground: analytically it stops after v0^2 / (2 mu_k g), at
// t = v0 / (mu_k g). Stopped: slower than 1 mm/s.
inline SlideResult slideToStop(const Settings& settings, double v0) {
  World world(settings);
  world.addPlane(Plane{}, caseMaterial());
  BodyDef box = caseBox(Vec3::UnitY(), caseMaterial());
  box.velocity = Vec3(v0, 0.0, 0.0);
  world.addBody(box);
  const double limit = 2.0 * v0 / (kCaseKineticFriction * kFrictionG) + 1.0;
  SlideResult out;
  while (world.time() < limit) {
    world.step();
    if (world.bodies()[0].velocity().norm() < 1e-3) break;
  }
  out.distance = world.bodies()[0].position().x();
  out.stopTime = world.time();
  return out;
}

struct InclineResult {
  double slide = 0.0;         // [m] down the slope over the time measured
  double acceleration = 0.0;  // [m/s^2] down the slope, mean over it
};

// The box released at rest on an incline of `degrees`: it stays when tan theta < mu_s, else it
// slides at g (sin theta - mu_k cos theta). Measured over `seconds` after a quarter second.
inline InclineResult incline(const Settings& settings, double degrees, double seconds) {
  const double theta = degrees * M_PI / 180.0;
  World world(settings);
  const Vec3 normal(-std::sin(theta), std::cos(theta), 0.0);  // the slope rises towards +x
  world.addPlane(Plane{normal, 0.0}, caseMaterial());
  world.addBody(caseBox(normal, caseMaterial()));
  const Vec3 downhill(-std::cos(theta), -std::sin(theta), 0.0);
  while (world.time() < 0.25 - 1e-9) world.step();
  const Vec3 start = world.bodies()[0].position();
  const double v1 = world.bodies()[0].velocity().dot(downhill), t1 = world.time();
  while (world.time() < t1 + seconds - 1e-9) world.step();
  InclineResult out;
  out.slide = (world.bodies()[0].position() - start).dot(downhill);
  out.acceleration = (world.bodies()[0].velocity().dot(downhill) - v1) / (world.time() - t1);
  return out;
}

struct BounceResult {
  double impactSpeed = 0.0;  // sqrt(2 g h) [m/s], analytic
  // The speed it left the ground with: at the end of the first step that ends rising, from its
  // height y above touching and its speed v there, sqrt(v^2 + 2 g max(y, 0)) (free flight keeps
  // it). A bounce reversed above the ground shows as the energy it gained.
  double leaveSpeed = 0.0;  // [m/s]
};

// The centre's height when the dropped body touches the ground: half the box, the ball's radius.
inline constexpr double kDropRestHeight = 0.1;  // [m]

// A body (a 0.4 x 0.2 x 0.4 m box, or a ball of radius 0.1 m when `ball`) with restitution c_R (the ground's
// too) dropped from `height` above the ground, at rest.
inline BounceResult dropAndBounce(const Settings& settings, double restitution, double height, bool ball) {
  World world(settings);
  world.addPlane(Plane{}, caseMaterial(restitution));
  BodyDef body = ball ? shapeBodyDef(Shape::sphere(0.1), 1.0, "ball") : caseBox(Vec3::UnitY(), caseMaterial(restitution));
  body.material = caseMaterial(restitution);
  body.position = Vec3(0.0, kDropRestHeight + height, 0.0);
  world.addBody(body);
  BounceResult out;
  out.impactSpeed = std::sqrt(2.0 * kFrictionG * height);
  const double limit = 2.0 * out.impactSpeed / kFrictionG + 0.5;
  bool fell = false;
  while (world.time() < limit) {
    world.step();
    const double vy = world.bodies()[0].velocity().y();
    if (vy < 0.0) fell = true;
    if (fell && vy >= 0.0) {
      // Below the touching height (within Settings::contactSlop, which the solvers leave alone)
      // it left from the surface: the depth is not energy it lacks.
      const double above = std::max(world.bodies()[0].position().y() - kDropRestHeight, 0.0);
      out.leaveSpeed = std::sqrt(std::max(vy * vy + 2.0 * kFrictionG * above, 0.0));
      break;
    }
  }
  return out;
}

}  // namespace rbsim::bench
