// integrate/integrator: dlm, the symplectic splitting of the free rigid body (Dullweber,
// Leimkuhler & McLachlan 1997), with torque as half kicks and x exact for constant force.
// Each test checks a property the method has by construction, on a case where other methods
// visibly lack it.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "rbsim/integrate/integrator.h"
#include "rbsim/math/rotation.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxDef;
using test::worldWith;

constexpr double kDt = 1.0 / 60.0;  // a game time step [s]

TEST(Dlm, FreeFallIsTheExactParabola) {
  // x += dt (P + dt F / 2) / m is exact for a constant force.
  World world = worldWith(Integrator::Dlm, 0.05, Vec3(0.0, -9.81, 0.0));
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 2.5);
  const Vec3 x0(0.0, 10.0, 0.0), v0(1.0, 2.0, -0.5), g(0.0, -9.81, 0.0);
  def.position = x0;
  def.velocity = v0;
  world.addBody(def);
  for (int i = 0; i < 200; ++i) world.step();
  const double t = world.time();
  const Vec3 exact = x0 + v0 * t + 0.5 * g * t * t;
  EXPECT_LE((world.bodies()[0].position() - exact).norm(), 1e-12 * exact.norm());
}

// The spec's asymmetric box spinning near its intermediate axis (the Dzhanibekov case).
struct DlmTumble {
  double energy0 = 0.0, momentum0 = 0.0;
  double maxEnergyError = 0.0;  // max |E / E0 - 1| over the run
  double momentum = 0.0;
};

DlmTumble tumble(Integrator integrator, double seconds) {
  World world = worldWith(integrator, kDt, Vec3::Zero());
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  def.angularVelocity = Vec3(0.01, 5.0, 0.01);
  world.addBody(def);
  const RigidBody& body = world.bodies()[0];
  DlmTumble out;
  out.energy0 = body.kineticEnergy();
  out.momentum0 = body.state().angularMomentum.norm();
  while (world.time() < seconds) {
    world.step();
    out.maxEnergyError = std::max(out.maxEnergyError, std::abs(body.kineticEnergy() / out.energy0 - 1.0));
  }
  out.momentum = body.state().angularMomentum.norm();
  return out;
}

TEST(Dlm, TorqueFreeKeepsLToTheBitAndEnergyInABand) {
  // The splitting never touches world L, and as a symplectic map its energy error oscillates
  // instead of growing. Measured over 100 s at dt = 1/60: max |E/E0 - 1| = 9.7e-5; expmap on the
  // same motion ends with 10.1 times the energy. Bound: 1e-3, ten times the measurement.
  const DlmTumble dlm = tumble(Integrator::Dlm, 100.0);
  std::printf("[ dlm ] max |E/E0 - 1| over 100 s at dt = 1/60: %.3e\n", dlm.maxEnergyError);
  EXPECT_EQ(dlm.momentum, dlm.momentum0);
  EXPECT_LT(dlm.maxEnergyError, 1e-3);
  const DlmTumble expmap = tumble(Integrator::ExpMap, 100.0);
  EXPECT_GT(expmap.maxEnergyError, 1.0) << "the case separates a symplectic splitting from forward Euler";
}

TEST(Dlm, NonDiagonalInertiaGivesTheSameMotionAsItsPrincipalBody) {
  // A box whose body axes are not its principal axes (mesh and tensor turned by Q) must move as
  // the principal box posed at Q: the splitting runs in the principal frame E from the body.
  const Vec3 extents(1.0, 0.3, 0.1);
  const Mat3 Q = rotationFromAxisAngle(Vec3(0.4, -0.3, 0.7));
  const Vec3 omega(0.3, 4.0, -0.2);  // world frame [rad/s]

  World principal = worldWith(Integrator::Dlm, kDt, Vec3::Zero());
  BodyDef a = boxDef(extents, 1.0);
  a.orientation = Quat(Q);
  a.angularVelocity = omega;
  principal.addBody(a);

  World turned = worldWith(Integrator::Dlm, kDt, Vec3::Zero());
  BodyDef b = boxDef(extents, 1.0);
  b.inertiaBody = Q * b.inertiaBody * Q.transpose();
  Mesh mesh = *b.mesh;
  for (Vec3& p : mesh.vertices) p = Q * p;
  b.mesh = std::make_shared<const Mesh>(mesh);
  b.angularVelocity = omega;
  turned.addBody(b);

  for (int i = 0; i < 600; ++i) {
    principal.step();
    turned.step();
  }
  // Same world vertices: the poses differ by Q inside, agree outside. Tolerance: rounding of
  // two different eigen-decompositions carried through 600 steps of a chaotic-ish tumble.
  for (std::size_t i = 0; i < principal.bodies()[0].vertexCount(); ++i) {
    EXPECT_TRUE(allNear(principal.bodies()[0].worldVertex(i), turned.bodies()[0].worldVertex(i), 1e-9)) << i;
  }
  EXPECT_TRUE(allNear(principal.bodies()[0].angularVelocity(), turned.bodies()[0].angularVelocity(), 1e-9));
}

TEST(Dlm, ConstantTorqueAboutAPrincipalAxisTurnsByTheExactIntegralOfOmega) {
  // L0 and tau along the box's principal z axis: omega = (L0 + tau t) / I3 about a fixed axis,
  // so the angle is (L0 t + tau t^2 / 2) / I3. With Pi_1 = Pi_2 = 0 only the axis-3 flow turns,
  // and the half kicks give each step the mean L of the step, which makes this exact, where
  // forward Euler lags by tau t dt / (2 I3).
  const BodyDef box = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  const double I = box.inertiaBody(2, 2);  // [kg m^2]
  const Vec3 axis = Vec3::UnitZ();
  const double L0 = 0.2, tau = 0.05;  // [kg m^2/s], [N m]
  const int steps = 45;               // t = 0.75 s: a total angle of 1.81 rad, inside (0, pi)
  double angle[2];
  int k = 0;
  for (Integrator integrator : {Integrator::Dlm, Integrator::ExpMap}) {
    World world = worldWith(integrator, kDt, Vec3::Zero());
    BodyDef def = box;
    def.angularVelocity = axis * (L0 / I);
    world.addBody(def);
    // The torque as a couple: F at a fixed world point r with r x F = tau axis, and -F at the
    // centre of mass, which stays at the origin because the net force is zero.
    const Vec3 F = Vec3::UnitX();  // [N], perpendicular to the axis
    const Vec3 r = F.cross(tau * axis);
    world.addForce({world.idAt(0), F, r, Frame::World, Frame::World, 0.0, 1e9});
    world.addForce({world.idAt(0), -F, Vec3::Zero(), Frame::World, Frame::World, 0.0, 1e9});
    for (int i = 0; i < steps; ++i) world.step();
    angle[k++] = rotationAngleBetween(Mat3::Identity(), world.bodies()[0].rotation());
    EXPECT_TRUE(allNear(world.bodies()[0].state().angularMomentum, axis * (L0 + tau * world.time()), 1e-13));
  }
  const double t = steps * kDt;
  const double exact = (L0 * t + 0.5 * tau * t * t) / I;
  std::printf("[ dlm ] angle %.6f rad, exact %.6f rad, expmap %.6f rad\n", angle[0], exact, angle[1]);
  EXPECT_NEAR(angle[0], exact, 1e-12);
  EXPECT_NEAR(angle[1], exact - tau * t * kDt / (2.0 * I), 1e-12) << "forward Euler's known lag";
}

}  // namespace
}  // namespace rbsim
