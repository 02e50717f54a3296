// world/free_flight_error: the overlay's live error of an integrator against the exact spin. It
// must read rounding for exact, the known failure for forward Euler (the Dzhanibekov flip lost,
// energy gained), the known loss for implicit-gyro, and restart when a contact turns the body.
#include "rbsim/world/free_flight_error.h"

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

// The box (1.0 x 0.3 x 0.1 m, 1 kg) spun near its intermediate axis, under gravity.
FreeFlightError::Reading flightTumble(Integrator integrator, double seconds) {
  World world = test::worldWith(integrator, 1.0 / 60.0, Vec3(0.0, -9.81, 0.0));
  BodyDef def = test::boxDef(Vec3(1.0, 0.3, 0.1), 1.0, "tumbler");
  def.orientation = Quat(rotationFromAxisAngle(Vec3(0.3, -0.2, 0.5)));
  def.angularVelocity = def.orientation * Vec3(0.01, 10.0, 0.0);
  world.addBody(def);
  FreeFlightError error(world.idAt(0));
  error.observe(world);
  for (long i = 0; i < std::lround(seconds * 60.0); ++i) {
    world.step();
    error.observe(world);
  }
  return error.read(world);
}

TEST(FreeFlightError, ReadsRoundingForExactAndTheKnownErrorsOfTheOthers) {
  const FreeFlightError::Reading exact = flightTumble(Integrator::Exact, 10.0);
  ASSERT_TRUE(exact.tracked);
  EXPECT_EQ(exact.since, 0.0);  // gravity exerts no torque: never restarted
  EXPECT_LT(exact.angle, 1e-9);
  EXPECT_LT(std::abs(exact.energy), 1e-12);
  const FreeFlightError::Reading expmap = flightTumble(Integrator::ExpMap, 10.0);
  EXPECT_GT(expmap.angle, 1.0);    // the flip lost: the body points elsewhere
  EXPECT_GT(expmap.energy, 0.5);   // forward Euler gains energy on the way to the long axis
  const FreeFlightError::Reading gyro = flightTumble(Integrator::ImplicitGyro, 10.0);
  EXPECT_LT(gyro.energy, -0.01);   // Catto's implicit step only ever loses energy
}

// A box thrown spinning onto the ground: while it touches, the reference restarts, so the
// reading's epoch is after the landing and the error is what exact added since: rounding.
TEST(FreeFlightError, RestartsAfterAContact) {
  Settings settings;
  settings.timeStep = 1.0 / 60.0;
  settings.integrator = Integrator::Exact;
  settings.allowSleep = false;  // a sleeping body is not tracked
  World world(settings);
  world.addPlane(Plane{});
  BodyDef def = test::boxDef(Vec3(1.0, 0.3, 0.1), 1.0, "thrown");
  def.position = Vec3(0.0, 1.0, 0.0);
  def.velocity = Vec3(0.0, 4.0, 0.0);
  def.angularVelocity = Vec3(2.0, 7.0, 1.0);
  world.addBody(def);
  FreeFlightError error(world.idAt(0));
  error.observe(world);
  bool landed = false;
  for (int i = 0; i < 120; ++i) {
    world.step();
    error.observe(world);
    for (const Contact& c : world.contacts()) landed = landed || c.b == 0;
  }
  ASSERT_TRUE(landed);
  const FreeFlightError::Reading r = error.read(world);
  ASSERT_TRUE(r.tracked);
  EXPECT_GT(r.since, 0.0);
  EXPECT_LT(r.angle, 1e-9);
}

}  // namespace
}  // namespace rbsim
