// Changes of a running body (world/body_changes.h: setBodyMass, setBodyMaterial, setBodyFilter; issue 57): each
// acts from the next step, on that body alone, and a refused one leaves the World as it was.
// Every case at dt = 1/60 and 1/240 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/body/shape_body.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/body_changes.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"
#include "test_util.h"
#include "refusal.h"

namespace rbsim::test::body_changes {
namespace {

constexpr double kG = 9.81;        // [m/s^2]
constexpr double kRadius = 0.1;    // the balls' [m]

class BodyChanges : public testing::TestWithParam<double> {
 protected:
  double dt() const { return GetParam(); }
  Settings settings() const {
    Settings s;
    s.timeStep = dt();
    s.gravity = Vec3(0.0, -kG, 0.0);
    s.allowSleep = false;
    // dlm, as restitution_sweep.py: its free flight peaks where the closed form does (symplectic
    // Euler's at 1/60 s comes 10 % lower: a rebound would read as a lower restitution).
    s.integrator = Integrator::Dlm;
    return s;
  }
};

BodyDef ball(const std::string& name, const Vec3& at, double restitution) {
  BodyDef def = shapeBodyDef(Shape::sphere(kRadius), 1.0, name);
  def.position = at;
  def.material.restitution = restitution;
  return def;
}

// A ball bouncing with c_R 0.5; between its first and second bounce its restitution becomes 0.8.
// The second rebound then rises to 0.8^2 of the height it fell from (Newton's law of restitution,
// seed 000), where 0.5^2 would have been 0.16 of it; a second ball bouncing beside it, whose
// material stays, moves bit for bit as in a run without the change.
TEST_P(BodyChanges, RestitutionChangedBetweenBouncesGivesTheNewReboundHeight) {
  constexpr double kDrop = 1.0, kFirst = 0.5, kSecond = 0.8;
  const auto run = [&](bool change, std::vector<BodyState>& control) {
    World world(settings());
    world.addPlane(Plane{});  // restitution 0: the pair takes the ball's, the larger
    const BodyId a = world.addBody(ball("a", Vec3(0.0, kRadius + kDrop, 0.0), kFirst));
    const BodyId b = world.addBody(ball("b", Vec3(3.0, kRadius + kDrop, 0.0), kFirst));
    int bounces = 0;
    double top = 0.0, lastVy = 0.0;
    std::vector<double> rebounds;
    for (int i = 0; i < static_cast<int>(4.0 / dt()) && rebounds.size() < 2; ++i) {
      world.step();
      control.push_back(world.body(b).state());
      const double vy = world.body(a).velocity().y(), height = world.body(a).position().y() - kRadius;
      if (lastVy <= 0.0 && vy > 0.0) ++bounces;  // went up: it bounced
      if (bounces > 0) top = std::max(top, height);
      if (bounces > 0 && lastVy > 0.0 && vy <= 0.0) {  // the top of a rebound
        rebounds.push_back(top);
        top = 0.0;
        bounces = 0;
        if (change && rebounds.size() == 1) setBodyMaterial(world, a, Material{kSecond, 0.6, 0.5});
      }
      lastVy = vy;
    }
    return rebounds;
  };
  std::vector<BodyState> changedControl, plainControl;
  const std::vector<double> changed = run(true, changedControl), plain = run(false, plainControl);
  ASSERT_EQ(changed.size(), 2u);
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(changed[0], plain[0]);  // nothing changed before the change
  // The collision pass reverses an approach up to |v| dt above the ground (docs/python.md,
  // restitution_sweep.py), which the rebound keeps (1 - e^2) of: the most it may come out high.
  const auto expectRebound = [&](double rebound, double from, double e) {
    const double speed = std::sqrt(2.0 * kG * from);
    EXPECT_GT(rebound, e * e * from - 1e-3) << "from " << from << " m with e = " << e;
    EXPECT_LT(rebound, e * e * from + (1.0 - e * e) * speed * dt() + 1e-3) << "from " << from << " m with e = " << e;
  };
  expectRebound(changed[1], changed[0], kSecond);
  expectRebound(plain[1], plain[0], kFirst);
  const std::size_t common = std::min(changedControl.size(), plainControl.size());
  for (std::size_t i = 0; i < common; ++i) {
    const BodyState &c = changedControl[i], &p = plainControl[i];  // equal to the bit (no NaN here)
    ASSERT_TRUE(c.position == p.position && c.orientation.coeffs() == p.orientation.coeffs() &&
                c.linearMomentum == p.linearMomentum && c.angularMomentum == p.angularMomentum)
        << "control ball, step " << i;
  }
}

// A body on a damped spring settles at x = anchor - rest - m g / k; doubling its mass moves it
// to the new equilibrium, m' g / k lower.
TEST_P(BodyChanges, MassChangeOnASpringGivesTheNewEquilibrium) {
  constexpr double kStiffness = 200.0, kDamping = 20.0;  // [N/m], [N s/m]: an underdamped 10 rad/s
  World world(settings());
  const BodyId id = world.addBody(boxDef(Vec3(0.2, 0.2, 0.2), 1.0));
  addSpring(world, Spring{id, Vec3::Zero(), Vec3::Zero(), kStiffness, 0.0, kDamping});
  const auto settle = [&] {
    for (int i = 0; i < static_cast<int>(6.0 / dt()); ++i) world.step();
  };
  settle();
  EXPECT_NEAR(world.body(id).position().y(), -1.0 * kG / kStiffness, 1e-6);
  const Mat3 inertia = world.body(id).inertiaBody();
  setBodyMass(world, id, 2.0, 2.0 * inertia);
  EXPECT_EQ(world.body(id).mass(), 2.0);
  settle();
  EXPECT_NEAR(world.body(id).position().y(), -2.0 * kG / kStiffness, 1e-6);
}

// The velocity and angular velocity stay through a change of mass and inertia; the momenta follow
// (P = m v, L = I omega). A copy of the World taken before keeps the old mass (they share the
// body's constants until the change).
TEST_P(BodyChanges, MassChangeKeepsTheVelocitiesAndLeavesCopiesAlone) {
  Settings s = settings();
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef def = boxDef(Vec3(0.4, 0.2, 0.1), 1.0);
  def.velocity = Vec3(1.0, 2.0, 3.0);
  def.angularVelocity = Vec3(0.3, -0.2, 0.1);
  const BodyId id = world.addBody(def);
  world.step();
  const World before = world;
  const Vec3 v = world.body(id).velocity(), omega = world.body(id).angularVelocity();
  const Mat3 inertia = cuboidInertia(3.0, Vec3(0.4, 0.2, 0.1));
  setBodyMass(world, id, 3.0, inertia);
  EXPECT_TRUE(allNear(world.body(id).velocity(), v, 1e-15));
  EXPECT_TRUE(allNear(world.body(id).angularVelocity(), omega, 1e-14));
  EXPECT_TRUE(allNear(world.body(id).state().linearMomentum, 3.0 * v, 1e-14));
  EXPECT_TRUE(allNear(world.body(id).state().angularMomentum, world.body(id).inertiaWorld() * omega, 1e-14));
  EXPECT_EQ(before.body(id).mass(), 1.0);
  EXPECT_TRUE(allNear(before.body(id).inertiaBody(), cuboidInertia(1.0, Vec3(0.4, 0.2, 0.1)), 0.0));
}

// A box on a 30 degree incline, held by mu_s = 0.7 > tan 30 = 0.577; friction 0.3 (both
// coefficients) lets it slide at g (sin - mu_k cos); then 0.9 stops it at g (mu_k cos - sin).
TEST_P(BodyChanges, FrictionChangeStartsAndStopsSlidingAtTheFrictionAngle) {
  const double theta = M_PI / 6.0;
  Settings s = settings();
  s.gravity = kG * Vec3(std::sin(theta), -std::cos(theta), 0.0);  // the incline as the ground, gravity tilted
  World world(s);
  world.addPlane(Plane{}, Material{0.0, 10.0, 10.0});  // the pair's mu is sqrt(mu_plane mu_box): 10 x
  BodyDef def = boxDef(Vec3(0.2, 0.2, 0.2), 1.0);
  def.position = Vec3(0.0, 0.1, 0.0);
  const auto material = [](double mu) { return Material{0.0, mu * mu / 10.0, mu * mu / 10.0}; };
  def.material = material(0.7);
  const BodyId id = world.addBody(def);
  const auto run = [&](double seconds) {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / dt())); ++i) world.step();
  };
  run(1.0);
  EXPECT_LT(std::abs(world.body(id).velocity().x()), 1e-3);  // held: tan 30 < 0.7
  const double x0 = world.body(id).position().x();
  setBodyMaterial(world, id, material(0.3));
  run(0.5);
  const double down = kG * (std::sin(theta) - 0.3 * std::cos(theta));  // 2.357 m/s^2
  EXPECT_NEAR(world.body(id).velocity().x(), down * 0.5, 0.02 * down * 0.5);
  EXPECT_GT(world.body(id).position().x() - x0, 0.5 * down * 0.25 * 0.9);
  setBodyMaterial(world, id, material(0.9));
  const double stop = kG * (0.9 * std::cos(theta) - std::sin(theta));  // 2.746 m/s^2
  run(world.body(id).velocity().x() / stop + 0.5);
  EXPECT_LT(std::abs(world.body(id).velocity().x()), 1e-3);  // stopped, and held again
}

// A box resting on a static box falls through it once its mask leaves out the static box's
// category: from the next step no contact holds it, and it falls freely (v = -g t exactly).
TEST_P(BodyChanges, FilterChangeLetsABodyPassThroughFromTheNextStep) {
  World world(settings());
  BodyDef floor = boxDef(Vec3(2.0, 0.2, 2.0), 1.0, "floor");
  floor.isStatic = true;
  floor.filter.category = 2;
  world.addBody(floor);
  BodyDef def = boxDef(Vec3(0.2, 0.2, 0.2), 1.0);
  def.position = Vec3(0.0, 0.2, 0.0);
  const BodyId id = world.addBody(def);
  for (int i = 0; i < static_cast<int>(1.0 / dt()); ++i) world.step();
  EXPECT_NEAR(world.body(id).position().y(), 0.2, 0.01);  // resting on the floor
  EXPECT_FALSE(world.contacts().empty());
  CollisionFilter filter;
  filter.mask = ~std::uint64_t{2};
  setBodyFilter(world, id, filter);
  EXPECT_EQ(world.body(id).filter(), filter);
  const double vy = world.body(id).velocity().y();
  const int steps = static_cast<int>(0.5 / dt());
  for (int i = 0; i < steps; ++i) {
    world.step();
    EXPECT_TRUE(world.contacts().empty()) << "step " << i;
  }
  EXPECT_NEAR(world.body(id).velocity().y(), vy - kG * steps * dt(), 1e-9);
}

// A new inertia acts from the next step, exact's kept flow included (it restarts when L or the
// moments are not its own): a tumbling box given another inertia moves on as a box built with it
// in the same state does.
TEST_P(BodyChanges, NewInertiaMovesOnAsABodyBuiltWithIt) {
  for (const Integrator integrator : {Integrator::Exact, Integrator::Dlm, Integrator::Rk4}) {
    Settings s = settings();
    s.gravity = Vec3::Zero();
    s.integrator = integrator;
    World changed(s);
    BodyDef def = boxDef(Vec3(0.4, 0.2, 0.1), 1.0);
    def.angularVelocity = Vec3(0.3, 2.0, 0.1);  // near the middle axis: tumbling
    const BodyId id = changed.addBody(def);
    for (int i = 0; i < 30; ++i) changed.step();
    // The same principal moments about other axes.
    const Mat3 inertia = cuboidInertia(1.0, Vec3(0.1, 0.2, 0.4));
    setBodyMass(changed, id, 1.0, inertia);
    World built(s);
    BodyDef same = boxDef(Vec3(0.4, 0.2, 0.1), 1.0);
    same.inertiaBody = inertia;
    same.position = changed.body(id).position();
    same.orientation = changed.body(id).orientation();
    same.velocity = changed.body(id).velocity();
    same.angularVelocity = changed.body(id).angularVelocity();
    const BodyId twin = built.addBody(same);
    for (int i = 0; i < 120; ++i) {
      changed.step();
      built.step();
    }
    EXPECT_TRUE(allNear(changed.body(id).orientation().coeffs(), built.body(twin).orientation().coeffs(), 1e-12))
        << integratorName(integrator);
    EXPECT_TRUE(allNear(changed.body(id).angularVelocity(), built.body(twin).angularVelocity(), 1e-12)) << integratorName(integrator);
  }
}

// A change wakes the body, and at the next step the island it sleeps in: a box asleep on another
// on the ground wakes with it when the lower one's friction changes.
TEST_P(BodyChanges, AChangeWakesTheBodyAndItsIsland) {
  Settings s = settings();
  s.allowSleep = true;
  World world(s);
  world.addPlane(Plane{});
  BodyDef lower = boxDef(Vec3(0.4, 0.2, 0.4), 1.0, "lower");
  lower.position = Vec3(0.0, 0.1, 0.0);
  BodyDef upper = boxDef(Vec3(0.4, 0.2, 0.4), 1.0, "upper");
  upper.position = Vec3(0.0, 0.3, 0.0);
  const BodyId a = world.addBody(lower), b = world.addBody(upper);
  for (int i = 0; i < static_cast<int>(3.0 / dt()); ++i) world.step();
  ASSERT_FALSE(world.body(a).awake());
  ASSERT_FALSE(world.body(b).awake());
  setBodyMaterial(world, a, Material{0.0, 0.3, 0.3});
  EXPECT_TRUE(world.body(a).awake());
  world.step();
  EXPECT_TRUE(world.body(b).awake());
}

// Every bad value is refused naming the call, the body, the field and the expectation, and the
// World is as before: its state hash, the body's mass, inertia, material and filter.
TEST_P(BodyChanges, BadValuesAreRefusedAndChangeNothing) {
  World world(settings());
  world.addPlane(Plane{});
  const BodyId id = world.addBody(ball("ball", Vec3(0.0, 0.5, 0.0), 0.3));
  world.step();
  const std::uint64_t hash = world.stateHash();
  const Mat3 inertia = world.body(id).inertiaBody();
  const auto refused = [&](auto change, const std::string& words) {
    expectRefused(change, words);
    EXPECT_EQ(world.stateHash(), hash);
    EXPECT_EQ(world.body(id).mass(), 1.0);
    EXPECT_TRUE(allNear(world.body(id).inertiaBody(), inertia, 0.0));
    EXPECT_EQ(bodyMaterial(world, id).restitution, 0.3);
    EXPECT_EQ(bodyMaterial(world, id).staticFriction, 0.6);
    EXPECT_EQ(world.body(id).filter(), CollisionFilter{});
  };
  refused([&] { setBodyMass(world, id, -1.0, inertia); }, "setBodyMass: body 'ball': mass: expected a positive number, got -1");
  refused([&] { setBodyMass(world, id, NAN, inertia); }, "body 'ball': mass: expected a finite number");
  refused([&] { setBodyMass(world, id, 1.0, -inertia); }, "body 'ball': inertia: expected a symmetric positive definite");
  Mat3 skew = inertia;
  skew(0, 1) = 1e-3;
  refused([&] { setBodyMass(world, id, 1.0, skew); }, "body 'ball': inertia: expected a symmetric positive definite");
  refused([&] { setBodyMass(world, id, 1e200, inertia * 1e200); }, "body 'ball': mass: a mass of 1e+200 kg");
  refused([&] { setBodyMaterial(world, id, Material{1.5, 0.6, 0.5}); }, "body 'ball': restitution: expected a coefficient in [0, 1]");
  refused([&] { setBodyMaterial(world, id, Material{0.5, -0.1, 0.0}); }, "body 'ball': friction_static: expected a finite value >= 0 (mu_s)");
  refused([&] { setBodyMaterial(world, id, Material{0.5, INFINITY, 0.5}); }, "body 'ball': friction_static: expected a finite value >= 0 (mu_s)");
  refused([&] { setBodyMaterial(world, id, Material{0.5, 0.4, 0.5}); }, "body 'ball': friction_kinetic: expected mu_k <= friction_static (mu_s)");
  EXPECT_THROW(setBodyMaterial(world, BodyId{}, Material{}), std::invalid_argument);  // a stale id
}

INSTANTIATE_TEST_SUITE_P(Dt, BodyChanges, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return "dt_1_" + std::to_string(std::lround(1.0 / info.param)); });

}  // namespace
}  // namespace rbsim::test::body_changes
