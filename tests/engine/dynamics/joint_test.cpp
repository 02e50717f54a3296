// Joints in the soft step (engine/src/dynamics/soft_step_joints.cpp): compound pendulums against
// their closed-form periods, the energy of a long swing, a hanging chain, the hinge's axis,
// motor and limits, and a door pushed at its handle (seed 004: torque about the hinge).
#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include "test_util.h"
#include "rbsim/world/world.h"
#include "../../sanitized_build.h"

namespace rbsim::test {
namespace {

constexpr double kGravity = 9.81;  // [m/s^2]

// A rod (a thin box, extents 0.1 x length x 0.1 m, 1 kg) hanging from a joint at its top end at
// the origin, turned by theta0 about z. Its pivot inertia about z: I_pivot = I_cm + m d^2.
struct Pendulum {
  double length = 1.0;  // [m]
  double mass = 1.0;    // [kg]
  double width = 0.1;   // [m]
  double d() const { return 0.5 * length; }
  double pivotInertia() const { return mass * (width * width + length * length) / 12.0 + mass * d() * d(); }
  double smallAnglePeriod() const { return 2.0 * M_PI * std::sqrt(pivotInertia() / (mass * kGravity * d())); }
  // T = 4 sqrt(I / (m g d)) K(sin(theta0 / 2)), K the complete elliptic integral of the first kind.
  double period(double theta0) const {
    return 4.0 * std::sqrt(pivotInertia() / (mass * kGravity * d())) * boost::math::ellint_1(std::sin(0.5 * theta0));
  }
};

Settings pendulumSettings(double dt, Integrator integrator = Integrator::Exact) {
  Settings s;
  s.timeStep = dt;
  s.gravity = Vec3(0.0, -kGravity, 0.0);
  s.allowSleep = false;
  s.integrator = integrator;
  return s;
}

World pendulumWorld(const Pendulum& p, double theta0, double dt, JointDef::Type type,
                    Integrator integrator = Integrator::Exact) {
  World world(pendulumSettings(dt, integrator));
  BodyDef def = boxDef(Vec3(p.width, p.length, p.width), p.mass, "rod");
  const Quat q(Eigen::AngleAxisd(theta0, Vec3::UnitZ()));
  def.orientation = q;
  def.position = q * Vec3(0.0, -p.d(), 0.0);
  world.addBody(def);
  JointDef joint;
  joint.type = type;
  joint.bodyA = world.idAt(0);
  joint.anchor = Vec3::Zero();
  joint.axis = Vec3::UnitZ();
  world.addJoint(joint);
  return world;
}

double swingAngle(const World& world) {
  const Vec3 x = world.bodies()[0].position();
  return std::atan2(x.x(), -x.y());
}

// The mean period over `periods` swings, from upward zero crossings of the angle (each
// interpolated linearly within its step).
double measuredPeriod(World& world, int periods) {
  std::vector<double> crossings;
  double previous = swingAngle(world);
  while (static_cast<int>(crossings.size()) <= periods) {
    const double t0 = world.time();
    world.step();
    const double now = swingAngle(world);
    if (previous < 0.0 && now >= 0.0) crossings.push_back(t0 + world.settings().timeStep * (-previous) / (now - previous));
    previous = now;
    if (world.time() > 100.0 * periods) break;
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

double pendulumEnergy(const World& world, const Pendulum& p) {
  const RigidBody& rod = world.bodies()[0];
  return rod.kineticEnergy() + p.mass * kGravity * rod.position().y();
}

struct PeriodCase {
  double dt;
  JointDef::Type type;
};

void PrintTo(const PeriodCase& c, std::ostream* os) {
  *os << (c.type == JointDef::Type::Ball ? "ball" : "hinge") << ", dt 1/" << std::lround(1.0 / c.dt) << " s";
}

class SmallAnglePeriod : public testing::TestWithParam<PeriodCase> {};

TEST_P(SmallAnglePeriod, MatchesTwoPiSqrtIOverMgdWithinHalfAPercent) {
  const Pendulum p;
  const double theta0 = 2.0 * M_PI / 180.0;  // sin(theta0/2) ~ theta0/2: K differs from pi/2 by 8e-5
  World world = pendulumWorld(p, theta0, GetParam().dt, GetParam().type);
  const double period = measuredPeriod(world, 10);
  std::printf("small-angle period, dt = 1/%.0f s: %.6f s, 2 pi sqrt(I/(m g d)) = %.6f s, ratio %.5f\n", 1.0 / GetParam().dt,
              period, p.smallAnglePeriod(), period / p.smallAnglePeriod());
  EXPECT_NEAR(period / p.smallAnglePeriod(), 1.0, 0.005) << "period " << period << " s, expected " << p.smallAnglePeriod();
}

INSTANTIATE_TEST_SUITE_P(Joints, SmallAnglePeriod,
                         testing::Values(PeriodCase{1.0 / 60.0, JointDef::Type::Ball}, PeriodCase{1.0 / 240.0, JointDef::Type::Ball},
                                         PeriodCase{1.0 / 60.0, JointDef::Type::Hinge},
                                         PeriodCase{1.0 / 240.0, JointDef::Type::Hinge}));

// A jointed body is advanced by the soft step, whatever world.integrator is: the same period.
class PendulumIntegrator : public testing::TestWithParam<Integrator> {};

TEST_P(PendulumIntegrator, LargeSwingPeriodMatchesTheEllipticIntegral) {
  const Pendulum p;
  const double theta0 = 120.0 * M_PI / 180.0;
  World world = pendulumWorld(p, theta0, 1.0 / 240.0, JointDef::Type::Hinge, GetParam());
  const double period = measuredPeriod(world, 5);
  std::printf("120 deg swing, dt = 1/240 s: %.6f s, 4 sqrt(I/(m g d)) K(sin 60 deg) = %.6f s, ratio %.5f\n", period,
              p.period(theta0), period / p.period(theta0));
  EXPECT_NEAR(period / p.period(theta0), 1.0, 0.005) << "period " << period << " s, expected " << p.period(theta0);
}

INSTANTIATE_TEST_SUITE_P(Joints, PendulumIntegrator,
                         testing::Values(Integrator::Exact, Integrator::EulerQuat, Integrator::Rk4),
                         integratorParamName);

TEST(Joints, LargeSwingPeriodAtSixtyHertz) {
  const Pendulum p;
  const double theta0 = 120.0 * M_PI / 180.0;
  World world = pendulumWorld(p, theta0, 1.0 / 60.0, JointDef::Type::Ball);
  const double period = measuredPeriod(world, 5);
  std::printf("120 deg swing, dt = 1/60 s: %.6f s, expected %.6f s, ratio %.5f\n", period, p.period(theta0),
              period / p.period(theta0));
  EXPECT_NEAR(period / p.period(theta0), 1.0, 0.005) << "period " << period << " s, expected " << p.period(theta0);
}

// 1e4 swings of a 30 degree pendulum at dt = 1/60 s. The soft step never gives a pendulum energy
// (its relax sweep removes the velocity along the rod at the new pose, which only takes), but it
// takes some: each substep's velocity along the rod at the new pose is projected away, and only
// part of it comes back through the soft correction of the stretch this leaves. Bounds, in units of the
// swing energy m g d (1 - cos theta0): E never above E0 + 1 % (the substeps' symplectic Euler
// lets E oscillate within a swing; measured 0.67 %), and at most 20 % lost over the 1e4 swings
// (measured 16 %, about 1.6e-5 a swing; without its soft correction the rod drifted off its
// pivot, |E - E0| reaching 30 times the swing energy).
TEST(Joints, EnergyStaysBoundedOverTenThousandSwings) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "5e5 steps of the joint code the other Joints tests run for seconds; the bound is the normal build's";
  Pendulum p;
  p.length = 0.25;  // T = 0.82 s: 1e4 swings in 5e5 steps
  const double theta0 = 30.0 * M_PI / 180.0;
  World world = pendulumWorld(p, theta0, 1.0 / 60.0, JointDef::Type::Ball);
  const double e0 = pendulumEnergy(world, p);
  const double swing = p.mass * kGravity * p.d() * (1.0 - std::cos(theta0));
  const double duration = 1e4 * p.period(theta0);
  double highest = e0, lowest = e0;
  while (world.time() < duration) {
    world.step();
    highest = std::max(highest, pendulumEnergy(world, p));
    lowest = std::min(lowest, pendulumEnergy(world, p));
  }
  EXPECT_LT(highest - e0, 0.01 * swing) << "E rose above E0 by " << highest - e0 << " J";
  EXPECT_LT(e0 - lowest, 0.2 * swing) << "E fell below E0 by " << e0 - lowest << " J of a swing energy " << swing << " J";
  std::printf("energy over 1e4 swings: max E - E0 = %.3g J, max E0 - E = %.4g J = %.4g of the swing energy %.4g J\n",
              highest - e0, e0 - lowest, (e0 - lowest) / swing, swing);
}

// Ten links of 0.3 m, 0.5 kg, each hung from the one above by a ball joint, the top one from the
// world; released at 45 degrees from the vertical, they swing and fold for 5 s.
TEST(Joints, ChainOfTenLinksHoldsItsJointsWithinAMillimetre) {
  Settings s = pendulumSettings(1.0 / 60.0);
  World world(s);
  const double linkLength = 0.3;
  const Vec3 down = Quat(Eigen::AngleAxisd(M_PI / 4.0, Vec3::UnitZ())) * Vec3(0.0, -1.0, 0.0);
  for (int i = 0; i < 10; ++i) {
    BodyDef def = boxDef(Vec3(0.05, linkLength, 0.05), 0.5, "link" + std::to_string(i));
    def.orientation = Quat(Eigen::AngleAxisd(M_PI / 4.0, Vec3::UnitZ()));
    def.position = (i + 0.5) * linkLength * down;
    world.addBody(def);
    JointDef joint;
    joint.bodyA = world.idAt(static_cast<std::size_t>(i));
    joint.bodyB = i == 0 ? kWorldAnchor : world.idAt(static_cast<std::size_t>(i - 1));
    joint.anchor = i * linkLength * down;
    world.addJoint(joint);
  }
  double worst = 0.0;
  while (world.time() < 5.0) {
    world.step();
    for (const Joint& j : world.joints()) {
      const RigidBody& a = world.bodies()[world.indexOf(j.def.bodyA)];
      const Vec3 onA = a.bodyToWorld(j.localAnchorMoving);
      const Vec3 onB = j.def.bodyB == kWorldAnchor ? j.localAnchorBase : world.bodies()[world.indexOf(j.def.bodyB)].bodyToWorld(j.localAnchorBase);
      worst = std::max(worst, (onA - onB).norm());
    }
  }
  std::printf("chain of 10 links: largest joint separation over 5 s %.3g m\n", worst);
  EXPECT_LT(worst, 1e-3) << "largest joint separation " << worst << " m";
}

// A box hinged to the world about z at one corner edge, thrown with an angular velocity off the
// axis: the hinge keeps only the part about its axis.
TEST(Joints, HingeLeavesOnlyTheMotionAboutItsAxis) {
  World world(pendulumSettings(1.0 / 60.0));
  BodyDef def = boxDef(Vec3(0.4, 0.6, 0.2), 2.0, "box");
  def.position = Vec3(0.2, -0.3, 0.0);
  def.angularVelocity = Vec3(3.0, -2.0, 1.0);
  world.addBody(def);
  JointDef joint;
  joint.bodyA = world.idAt(0);
  joint.type = JointDef::Type::Hinge;
  joint.anchor = Vec3::Zero();
  joint.axis = Vec3::UnitZ();
  world.addJoint(joint);
  double worstOffAxis = 0.0, worstAxis = 0.0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const RigidBody& box = world.bodies()[0];
    const Vec3 w = box.angularVelocity();
    worstOffAxis = std::max(worstOffAxis, std::hypot(w.x(), w.y()));
    worstAxis = std::max(worstAxis, (box.rotation() * Vec3::UnitZ() - Vec3::UnitZ()).norm());
  }
  std::printf("hinge: largest off-axis |omega| %.3g rad/s, largest tilt of the axis %.3g\n", worstOffAxis, worstAxis);
  EXPECT_LT(worstOffAxis, 1e-3) << "rad/s";
  EXPECT_LT(worstAxis, 1e-3) << "the body's z axis left the hinge axis by this much";
}

// A wheel (a 1 x 1 x 0.2 m box of 3 kg) on a hinge through its centre, without gravity: a motor of
// at most 2 N m spins it up at tau / I and holds the target speed.
TEST(Joints, MotorSpinsUpAtItsTorqueAndHoldsItsSpeed) {
  Settings s = pendulumSettings(1.0 / 60.0);
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef def = boxDef(Vec3(1.0, 1.0, 0.2), 3.0, "wheel");
  world.addBody(def);
  JointDef joint;
  joint.bodyA = world.idAt(0);
  joint.type = JointDef::Type::Hinge;
  joint.axis = Vec3::UnitZ();
  joint.motor = true;
  joint.motorSpeed = 4.0;
  joint.maxMotorTorque = 2.0;
  world.addJoint(joint);
  const double inertia = 3.0 * (1.0 + 1.0) / 12.0;  // about z [kg m^2]
  world.step();
  EXPECT_NEAR(world.bodies()[0].angularVelocity().z(), 2.0 / inertia * s.timeStep, 1e-9);
  for (int i = 0; i < 120; ++i) world.step();  // 2 s; it reaches 4 rad/s after I w / tau = 1 s
  EXPECT_NEAR(world.bodies()[0].angularVelocity().z(), 4.0, 1e-9);
  EXPECT_NEAR(world.bodies()[0].angularVelocity().head<2>().norm(), 0.0, 1e-9);
}

// A rod on a hinge with limits [-0.3, 0.3] rad, started hanging at 3 rad/s about the pivot (it
// would swing to 1.1 rad): the angle stays within the limits, up to the soft limit's give.
TEST(Joints, LimitsHoldTheAngle) {
  const Pendulum p;
  World limitedWorld(pendulumSettings(1.0 / 60.0));
  BodyDef def = boxDef(Vec3(p.width, p.length, p.width), p.mass, "rod");
  def.position = Vec3(0.0, -p.d(), 0.0);
  def.angularVelocity = Vec3(0.0, 0.0, 3.0);
  def.velocity = def.angularVelocity.cross(def.position);  // turning about the pivot
  limitedWorld.addBody(def);
  JointDef joint;
  joint.bodyA = limitedWorld.idAt(0);
  joint.type = JointDef::Type::Hinge;
  joint.axis = Vec3::UnitZ();
  joint.limits = true;
  joint.lowerAngle = -0.3;
  joint.upperAngle = 0.3;
  limitedWorld.addJoint(joint);
  double lowest = 0.0, highest = 0.0;
  for (int i = 0; i < 600; ++i) {
    limitedWorld.step();
    const double angle = swingAngle(limitedWorld);
    lowest = std::min(lowest, angle);
    highest = std::max(highest, angle);
  }
  std::printf("limits [-0.3, 0.3] rad: angle within [%.5f, %.5f] rad\n", lowest, highest);
  EXPECT_LT(highest, 0.3 + 0.01);
  EXPECT_GT(lowest, -0.3 - 0.01);
  EXPECT_GT(highest, 0.29);  // it did reach the limit
}

// A door on a hinge with stops at +-0.5 rad, driven by a motor of 1e6 N m at 5 rad/s either way:
// it comes to rest against the stop it is driven into, at 1/60 and 1/240 s. The motor stops
// pushing at a stop, so the stop holds whatever its torque.
TEST(Joints, LimitsHoldAgainstAnyMotor) {
  for (double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    for (double speed : {5.0, -5.0}) {
      Settings s = pendulumSettings(dt);
      s.gravity = Vec3::Zero();
      World world(s);
      BodyDef door = boxDef(Vec3(1.0, 2.0, 0.05), 20.0, "door");
      door.position = Vec3(0.5, 0.0, 0.0);
      world.addBody(door);
      JointDef hinge;
      hinge.bodyA = world.idAt(0);
      hinge.type = JointDef::Type::Hinge;
      hinge.anchor = Vec3::Zero();
      hinge.axis = Vec3::UnitY();
      hinge.motor = true;
      hinge.motorSpeed = speed;
      hinge.maxMotorTorque = 1e6;
      hinge.limits = true;
      hinge.lowerAngle = -0.5;
      hinge.upperAngle = 0.5;
      world.addJoint(hinge);
      double widest = 0.0;
      for (int i = 0; i < static_cast<int>(std::lround(2.0 / dt)); ++i) {
        world.step();
        const Vec3 x = world.bodies()[0].position();
        widest = std::max(widest, std::abs(std::atan2(x.z(), x.x())));  // the door's turn about y
      }
      const Vec3 x = world.bodies()[0].position();
      const double final = std::abs(std::atan2(x.z(), x.x()));
      std::printf("motor %+.0f rad/s at 1e6 N m, dt %.5f s: widest %.5f rad, at rest %.5f rad\n", speed, dt, widest, final);
      EXPECT_LT(widest, 0.5 + 0.01) << "dt " << dt << ", speed " << speed;  // the soft stop's give at 5 rad/s
      EXPECT_NEAR(final, 0.5, 1e-3) << "dt " << dt << ", speed " << speed;
      EXPECT_LT(world.bodies()[0].angularVelocity().norm(), 1e-3) << "dt " << dt << ", speed " << speed;
    }
  }
}

// Seed 004: a door (1 m wide, 2 m tall, 0.05 m thick, 20 kg) hinged at its edge about the
// vertical, pushed at its handle 0.9 m from the hinge by 10 N normal to it: angular acceleration
// tau / I_hinge with I_hinge = m (w^2 + t^2) / 12 + m (w / 2)^2, whatever the integrator.
class DoorIntegrator : public testing::TestWithParam<Integrator> {};

TEST_P(DoorIntegrator, PushedAtItsHandleTurnsAtTorqueOverHingeInertia) {
  Settings s = pendulumSettings(1.0 / 240.0, GetParam());
  World world(s);
  const double mass = 20.0, width = 1.0, height = 2.0, thickness = 0.05;
  BodyDef def = boxDef(Vec3(width, height, thickness), mass, "door");
  def.position = Vec3(0.5 * width, 0.0, 0.0);
  world.addBody(def);
  JointDef hinge;
  hinge.bodyA = world.idAt(0);
  hinge.type = JointDef::Type::Hinge;
  hinge.anchor = Vec3::Zero();
  hinge.axis = Vec3::UnitY();
  world.addJoint(hinge);
  ScriptedForce push;
  push.body = world.idAt(0);
  push.force = Vec3(0.0, 0.0, -10.0);  // in the door's frame: normal to the door
  push.forceFrame = Frame::Body;
  push.point = Vec3(0.4, 0.0, 0.0);  // the handle, 0.9 m from the hinge
  push.pointFrame = Frame::Body;
  push.start = 0.0;
  push.end = 1e9;
  world.addForce(push);
  const double inertia = mass * (width * width + thickness * thickness) / 12.0 + mass * 0.25 * width * width;
  const double alpha = 10.0 * 0.9 / inertia;  // [rad/s^2] about +y
  for (int i = 0; i < 240; ++i) world.step();  // 1 s
  std::printf("door: omega_y / (alpha t) after 1 s = %.6f (alpha = tau / I_hinge = %.5f rad/s^2)\n",
              world.bodies()[0].angularVelocity().y() / (alpha * world.time()), alpha);
  EXPECT_NEAR(world.bodies()[0].angularVelocity().y() / (alpha * world.time()), 1.0, 1e-3);
  // The hinge still holds the door's edge at the axis.
  const Vec3 edge = world.bodies()[0].bodyToWorld(Vec3(-0.5 * width, 0.0, 0.0));
  EXPECT_LT(edge.norm(), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Joints, DoorIntegrator, testing::Values(Integrator::Exact, Integrator::SymplecticEuler),
                         integratorParamName);

}  // namespace
}  // namespace rbsim::test
