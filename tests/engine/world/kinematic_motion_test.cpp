// Kinematic bodies on a prescribed motion (world/kinematic_motion.h): turning about an axis
// through a point stays exactly on the circle, keyframes are met exactly at their times, and a
// turntable carries a box by friction as the analytic case says. At dt = 1/60 s and 1/240 s.
#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::allNear;

class KinematicMotionTest : public testing::TestWithParam<double> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam();
    return s;
  }
  int steps(double seconds) const { return static_cast<int>(std::lround(seconds / GetParam())); }
  static BodyDef kinematicBox(const Vec3& position, const Vec3& halfExtents = Vec3(0.5, 0.1, 0.5)) {
    BodyDef def = shapeBodyDef(Shape::box(halfExtents), 10.0, "kinematic");
    def.isKinematic = true;
    def.position = position;
    return def;
  }
};

// A door 1 m from its hinge line (the z axis through (0, 0, 0)) turning at 2 rad/s: after t its
// centre is the start turned by 2 t about z, exactly (to rounding), and so is its orientation.
TEST_P(KinematicMotionTest, TurningAboutAPivotStaysOnTheCircle) {
  World w(settings());
  const BodyId door = w.addBody(kinematicBox(Vec3(1.0, 0.0, 0.0)));
  KinematicMotion m;
  m.body = door;
  m.pivot = Vec3::Zero();
  m.angularVelocity = Vec3(0.0, 0.0, 2.0);
  setKinematicMotion(w, m);
  const int n = steps(1.3);
  for (int i = 0; i < n; ++i) w.step();
  const double t = n * GetParam();
  const Mat3 turn = rotationFromAxisAngle(t * m.angularVelocity);
  EXPECT_TRUE(allNear(w.body(door).position(), turn * Vec3(1.0, 0.0, 0.0), 1e-9));
  EXPECT_TRUE(allNear(w.body(door).rotation(), turn, 1e-9));
  // Its velocity is the chord's over the last step: omega x r to within omega^2 r dt / 2.
  const Vec3 tangent = m.angularVelocity.cross(w.body(door).position());
  EXPECT_TRUE(allNear(w.body(door).velocity(), tangent, 2.0 * 2.0 * GetParam()));
}

// A lift on three keyframes: up 2 m in 1 s, turning a quarter about y, then across 1 m in 1 s.
// At each key's time it is at the key exactly, halfway between them it is halfway, after the last
// it rests; looped, 2.5 s is 0.5 s again.
TEST_P(KinematicMotionTest, KeyframesAreMetAtTheirTimes) {
  for (const bool loop : {false, true}) {
    World w(settings());
    const BodyId lift = w.addBody(kinematicBox(Vec3::Zero()));
    KinematicMotion m;
    m.body = lift;
    m.kind = KinematicMotion::Kind::Keyframes;
    m.loop = loop;
    const Quat quarter(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
    m.keys = {{0.0, Vec3::Zero(), Quat::Identity()}, {1.0, Vec3(0, 2, 0), quarter}, {2.0, Vec3(1, 2, 0), quarter}};
    setKinematicMotion(w, m);
    const auto at = [&](double seconds) {
      while (w.time() < seconds - 0.5 * GetParam()) w.step();
    };
    at(0.5);
    EXPECT_TRUE(allNear(w.body(lift).position(), Vec3(0, 1, 0), 1e-9));
    EXPECT_LT(w.body(lift).orientation().angularDistance(Quat::Identity().slerp(0.5, quarter)), 1e-9);
    at(1.0);
    EXPECT_TRUE(allNear(w.body(lift).position(), Vec3(0, 2, 0), 1e-9));
    EXPECT_LT(w.body(lift).orientation().angularDistance(quarter), 1e-9);
    at(2.5);
    if (loop) {
      EXPECT_TRUE(allNear(w.body(lift).position(), Vec3(0, 1, 0), 1e-9));
    } else {
      EXPECT_TRUE(allNear(w.body(lift).position(), Vec3(1, 2, 0), 1e-9));
      EXPECT_LT(w.body(lift).velocity().norm(), 1e-9);
    }
  }
}

// A box at rest 0.5 m from the axis of a turntable that starts turning at 1 rad/s: kinetic
// friction (mu_k = 0.5) brings it to the table's speed omega R in omega R / (mu_k g), lagging by
// about (omega R)^2 / (2 mu_k g R) = 0.051 rad; from then on static friction holds it on its
// circle (omega^2 R = 0.5 m/s^2 < mu_s g), turning with the table.
TEST_P(KinematicMotionTest, ATurntableCarriesABoxByFriction) {
  World w(settings());
  const double omega = 1.0, R = 0.5, g = 9.81, muK = Material{}.kineticFriction;
  const BodyId table = w.addBody(kinematicBox(Vec3::Zero(), Vec3(1.0, 0.1, 1.0)));
  KinematicMotion m;
  m.body = table;
  m.angularVelocity = Vec3(0.0, omega, 0.0);
  setKinematicMotion(w, m);
  BodyDef box = shapeBodyDef(Shape::box(Vec3::Constant(0.1)), 1.0, "box");
  box.position = Vec3(R, 0.2, 0.0);
  const BodyId id = w.addBody(box);
  const double t = 2.0;
  for (int i = 0; i < steps(t); ++i) w.step();
  const RigidBody& b = w.body(id);
  const Vec3 radial(b.position().x(), 0.0, b.position().z());
  EXPECT_NEAR(radial.norm(), R, 0.01) << "held on its circle";
  EXPECT_NEAR(b.velocity().norm(), omega * radial.norm(), 0.01 * omega * R);
  EXPECT_NEAR(b.angularVelocity().y(), omega, 0.01 * omega) << "turning with the table";
  EXPECT_NEAR(b.position().y(), 0.2, 2e-3);
  // The table has turned omega t; the box lags by the sliding phase's slip.
  const double boxAngle = std::atan2(-b.position().z(), b.position().x());  // about +y
  const double lag = omega * t - boxAngle;
  const double expected = std::pow(omega * R, 2) / (2.0 * muK * g * R);
  EXPECT_NEAR(lag, expected, 0.25 * expected);
}

TEST(KinematicMotion, BadMotionsAreRefused) {
  World w{Settings{}};
  BodyDef dynamic = shapeBodyDef(Shape::sphere(0.5), 1.0, "ball");
  const BodyId ball = w.addBody(dynamic);
  dynamic.isKinematic = true;
  dynamic.name = "k";
  const BodyId k = w.addBody(dynamic);
  KinematicMotion m;
  m.body = ball;
  EXPECT_THROW(setKinematicMotion(w, m), std::invalid_argument);  // not kinematic
  m.body = k;
  m.kind = KinematicMotion::Kind::Keyframes;
  EXPECT_THROW(setKinematicMotion(w, m), std::invalid_argument);  // no keys
  m.keys = {{1.0, Vec3::Zero(), Quat::Identity()}, {1.0, Vec3::Ones(), Quat::Identity()}};
  EXPECT_NE(checkKinematicMotion(m).find("keys[1].time"), std::string::npos);
  m.keys = {{1.0, Vec3::Zero(), Quat(2, 0, 0, 0)}};
  EXPECT_NE(checkKinematicMotion(m).find("keys[0].orientation"), std::string::npos);
  m.keys = {{1.0, Vec3::Zero(), Quat::Identity()}};
  m.loop = true;
  EXPECT_NE(checkKinematicMotion(m).find("loop"), std::string::npos);
  m.kind = KinematicMotion::Kind::Pivot;
  m.angularVelocity = Vec3(0, std::nan(""), 0);
  EXPECT_THROW(setKinematicMotion(w, m), std::invalid_argument);
  EXPECT_TRUE(kinematicMotions(w).empty());
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, KinematicMotionTest, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

}  // namespace
}  // namespace rbsim
