#include "accuracy/cases.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/world.h"
#include "reference/torque_free.h"

namespace rbsim::accuracy {

namespace {

// Case 1: the box of tests/engine/reference (dzhanibekov_test, convergence_test), I1 < I2 < I3
// along body x, y, z, spun almost exactly about y so it flips over every half period.
const Vec3 kBoxExtents(1.0, 0.3, 0.1);       // [m]
constexpr double kBoxMass = 1.0;             // [kg]
const Vec3 kBoxOmegaBody(0.01, 5.0, 0.01);   // [rad/s], body frame
// A generic start orientation, so no world axis is special and errors in every component show.
const Vec3 kBoxR0AxisAngle(0.3, -0.2, 0.5);  // [rad]

// Case 2: a square plate, I1 = I2 = m (a^2 + c^2) / 12 < I3 = m a^2 / 6, spun mostly about its
// symmetry axis z with a transverse component, so omega precesses in the body at
// (I3 - I1) / I1 w3 ~ 7 rad/s and the plate wobbles visibly in space.
const Vec3 kTopExtents(0.4, 0.4, 0.1);       // [m]
constexpr double kTopMass = 1.0;             // [kg]
const Vec3 kTopOmegaBody(1.5, 0.0, 8.0);     // [rad/s], body frame
const Vec3 kTopR0AxisAngle(0.4, 0.0, 0.0);   // [rad], a 23 degree tilt about world x

// Case 3: a small brick thrown up and sideways under gravity, spinning near its major axis (a
// stable spin, far from the separatrix), so position and orientation both have exact solutions.
const Vec3 kBrickExtents(0.2, 0.1, 0.05);         // [m]
constexpr double kBrickMass = 0.5;                // [kg]
const Vec3 kBrickOmegaBody(0.5, 0.5, 6.0);        // [rad/s], body frame
const Vec3 kBrickR0AxisAngle(-0.2, 0.6, 0.1);     // [rad]
const Vec3 kBrickPosition(0.0, 1.0, 0.0);         // [m]
const Vec3 kBrickVelocity(4.0, 12.0, -1.0);       // [m/s]
const Vec3 kGravity(0.0, -9.81, 0.0);             // [m/s^2]

// Case 4: the box of case 1 spun (0.3, 4, -0.5) rad/s under a couple fixed in the body: forces
// +-(0, 0.05, 0.08) N at +-(0.2, 0, 0) m, torque 2 r x f = (0, -0.032, 0.02) N m, no net force.
const Vec3 kTorquedOmegaBody(0.3, 4.0, -0.5);  // [rad/s]
const Vec3 kCoupleArm(0.2, 0.0, 0.0);          // [m], body frame
const Vec3 kCoupleForce(0.0, 0.05, 0.08);      // [N], body frame
// Its reference: world-frame RK4 (fourth order, |L| exact) at this step, recorded on a grid
// every dt of the sweep (1/30 ... 1/1000 s) falls on.
constexpr int kReferenceRate = 30000;  // 1 / dt [1/s]
constexpr int kReferenceGrid = 6000;   // samples per second [1/s]

// The exact flips are counted on this grid: far finer than the ~4.4 s between them, and a
// crossing is never missed because the omega component is smooth and monotone near its zeros.
constexpr double kFlipCountGrid = 1e-3;  // [s]

BodyDef boxBody(const std::string& name, const Vec3& extents, double mass, const Mat3& R0,
                const Vec3& omegaBody) {
  BodyDef def;
  def.name = name;
  def.mesh = std::make_shared<const Mesh>(makeBox(extents));
  def.mass = mass;
  def.inertiaBody = cuboidInertia(mass, extents);
  def.orientation = Quat(R0);
  def.angularVelocity = R0 * omegaBody;  // world frame
  return def;
}

// Sign changes of the exact omega_body[axis] over (0, duration].
int countSignChanges(const reference::TorqueFreeExact& exact, int axis, double duration) {
  int count = 0;
  double previous = exact.omegaBody(0.0)[axis];
  const long samples = std::lround(duration / kFlipCountGrid);
  for (long i = 1; i <= samples; ++i) {
    const double value = exact.omegaBody(static_cast<double>(i) * kFlipCountGrid)[axis];
    if ((previous < 0.0) != (value < 0.0)) ++count;
    previous = value;
  }
  return count;
}

ReferenceCase torqueFreeBox(double duration) {
  const Mat3 R0 = rotationFromAxisAngle(kBoxR0AxisAngle);
  ReferenceCase c;
  c.name = "torque-free-box";
  c.description = "asymmetric box 1.0 x 0.3 x 0.1 m, omega0 = (0.01, 5, 0.01) rad/s near the intermediate axis";
  c.body = boxBody("box", kBoxExtents, kBoxMass, R0, kBoxOmegaBody);
  const auto exact = std::make_shared<const reference::TorqueFreeExact>(c.body.inertiaBody.diagonal(), kBoxOmegaBody, R0);
  c.exactRotation = [exact](double t) { return exact->rotation(t); };
  c.exactPosition = [](double) { return Vec3::Zero(); };
  c.flips = true;
  c.flipAxis = 1;
  c.exactHalfPeriod = exact->period() / 2.0;
  c.exactFlipCount = countSignChanges(*exact, c.flipAxis, duration);
  return c;
}

ReferenceCase symmetricTop() {
  const Mat3 R0 = rotationFromAxisAngle(kTopR0AxisAngle);
  ReferenceCase c;
  c.name = "symmetric-top";
  c.description = "square plate 0.4 x 0.4 x 0.1 m (I1 = I2 < I3), omega0 = (1.5, 0, 8) rad/s, tilted";
  c.body = boxBody("plate", kTopExtents, kTopMass, R0, kTopOmegaBody);
  const Vec3 moments = c.body.inertiaBody.diagonal();
  const auto exact = std::make_shared<const reference::SymmetricTopExact>(moments.x(), moments.z(), kTopOmegaBody, R0);
  c.exactRotation = [exact](double t) { return exact->rotation(t); };
  c.exactPosition = [](double) { return Vec3::Zero(); };
  return c;
}

ReferenceCase projectile() {
  const Mat3 R0 = rotationFromAxisAngle(kBrickR0AxisAngle);
  ReferenceCase c;
  c.name = "projectile";
  c.description = "brick 0.2 x 0.1 x 0.05 m thrown at (4, 12, -1) m/s under g = 9.81 m/s^2, spinning about its major axis";
  c.body = boxBody("brick", kBrickExtents, kBrickMass, R0, kBrickOmegaBody);
  c.body.position = kBrickPosition;
  c.body.velocity = kBrickVelocity;
  c.gravity = kGravity;
  // Gravity acts at the centre of mass, so the spin is torque-free.
  const auto exact = std::make_shared<const reference::TorqueFreeExact>(c.body.inertiaBody.diagonal(), kBrickOmegaBody, R0);
  c.exactRotation = [exact](double t) { return exact->rotation(t); };
  c.exactPosition = [](double t) { return reference::projectile(kBrickPosition, kBrickVelocity, kGravity, t); };
  return c;
}

ReferenceCase torquedBox(double duration) {
  const Mat3 R0 = rotationFromAxisAngle(kBoxR0AxisAngle);
  ReferenceCase c;
  c.name = "torqued-box";
  c.description = "the box of case 1, omega0 = (0.3, 4, -0.5) rad/s, under a torque (0, -0.032, 0.02) N m fixed in the body";
  c.body = boxBody("box", kBoxExtents, kBoxMass, R0, kTorquedOmegaBody);
  c.conservative = false;
  for (double sign : {1.0, -1.0}) {
    ScriptedForce f;
    f.force = sign * kCoupleForce;
    f.point = sign * kCoupleArm;
    f.forceFrame = Frame::Body;
    f.pointFrame = Frame::Body;
    f.end = 2.0 * duration;
    c.forces.push_back(f);
  }
  Settings settings;
  settings.gravity = Vec3::Zero();
  settings.timeStep = 1.0 / kReferenceRate;
  settings.integrator = Integrator::Rk4;
  settings.allowSleep = false;
  World world(settings);
  const BodyId body = world.addBody(c.body);
  for (ScriptedForce f : c.forces) {  // the case's forces name no body until it is in a World
    f.body = body;
    world.addForce(f);
  }
  const long samples = std::lround(duration * kReferenceGrid) + 1;
  auto grid = std::make_shared<std::vector<Quat>>();
  grid->reserve(static_cast<std::size_t>(samples));
  grid->push_back(world.bodies()[0].orientation());
  for (long i = 1; i < samples; ++i) {
    for (int k = 0; k < kReferenceRate / kReferenceGrid; ++k) world.step();
    grid->push_back(world.bodies()[0].orientation());
  }
  c.exactRotation = [grid](double t) {
    const long i = std::lround(t * kReferenceGrid);
    if (i < 0 || i >= static_cast<long>(grid->size())) throw std::out_of_range("torqued-box: no reference at this time");
    return Mat3((*grid)[static_cast<std::size_t>(i)].toRotationMatrix());
  };
  c.exactPosition = [](double) { return Vec3::Zero(); };
  return c;
}

}  // namespace

std::vector<ReferenceCase> referenceCases(double duration) {
  return {torqueFreeBox(duration), symmetricTop(), projectile(), torquedBox(duration)};
}

}  // namespace rbsim::accuracy
