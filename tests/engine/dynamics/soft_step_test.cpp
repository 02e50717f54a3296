// The soft-step solver (engine/include/rbsim/dynamics/soft_step_solver.h) on issue 18's scenes, at the time
// step users pick (1/60 s) and at 1/240 s, with its defaults: tall stacks and a pyramid stand,
// mass ratios stand, a thin plate rests, bounces keep e^2 of their height and never gain energy
// in the contact, free flight is untouched, and the solved impulses meet seed 001's conditions to
// the accuracy one relax sweep per substep gives.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "../../sanitized_build.h"
#include "dynamics_util.h"
#include "rbsim/body/shape_body.h"

namespace rbsim {
namespace {

constexpr double kDt60 = 1.0 / 60.0;    // [s]
constexpr double kDt240 = 1.0 / 240.0;  // [s]

Settings settingsAt(double dt, Integrator integrator = Settings{}.integrator) {
  Settings s;
  s.timeStep = dt;
  s.allowSleep = false;  // the assertions are about the solver, not about sleeping hiding motion
  s.integrator = integrator;
  return s;
}

Material softFriction(double mu, double restitution = 0.0) { return Material{restitution, mu, mu}; }

// Unit boxes of 1 kg, softFriction 0.6, centres at `centres` (touching), on the ground plane.
World boxes(const Settings& settings, const std::vector<Vec3>& centres, const Vec3& extents = Vec3::Ones()) {
  World world(settings);
  world.addPlane(Plane{}, softFriction(0.6));
  for (std::size_t i = 0; i < centres.size(); ++i) {
    world.addBody(test::boxWith(extents, 1.0, centres[i], softFriction(0.6), "box" + std::to_string(i)));
  }
  return world;
}

std::vector<Vec3> column(int count) {
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i) out.emplace_back(0.0, 0.5 + i, 0.0);
  return out;
}

std::vector<Vec3> pyramid(int rows) {
  std::vector<Vec3> out;
  for (int r = 0; r < rows; ++r) {
    for (int i = 0; i < rows - r; ++i) out.emplace_back(i - 0.5 * (rows - r - 1), 0.5 + r, 0.0);
  }
  return out;
}

void run(World& world, double seconds) {
  while (world.time() < seconds - 1e-9) world.step();
}

double horizontalDrift(const Vec3& a, const Vec3& b) { return Vec3(a.x() - b.x(), 0.0, a.z() - b.z()).norm(); }

std::vector<Integrator> allIntegrators() {
  std::vector<Integrator> out;
  for (const std::string& name : integratorNames()) {
    Integrator i;
    parseIntegrator(name, i);
    out.push_back(i);
  }
  return out;
}

// Issue 18: with PGS at dt = 1/60 a column of 20 toppled (top 11.7 m away with dlm).
TEST(SoftStep, ColumnsOfTwentyAndFortyStandAtSixtyHertzWithEveryIntegrator) {
  // Under the sanitizers one integrator (73 s of CI for all nine): bodies in contact do not
  // depend on it, bit for bit (the next test), which runs there too.
  const std::vector<Integrator> integrators =
      test::kSanitizedBuild ? std::vector<Integrator>{Integrator::ExpMap} : allIntegrators();
  // And 4 s of standing there, 240 steps (the normal build stands them 10 s).
  const double kColumnSeconds = test::kSanitizedBuild ? 4.0 : 10.0;  // [s]
  for (Integrator integrator : integrators) {
    World twenty = boxes(settingsAt(kDt60, integrator), column(20));
    run(twenty, kColumnSeconds);
    const RigidBody& top = twenty.bodies().back();
    EXPECT_LT(horizontalDrift(top.position(), Vec3(0.0, 19.5, 0.0)), 0.01) << integratorName(integrator);
    EXPECT_LT(19.5 - top.position().y(), 0.01) << "height lost, " << integratorName(integrator);
    World forty = boxes(settingsAt(kDt60, integrator), column(40));
    run(forty, kColumnSeconds);
    EXPECT_LT(horizontalDrift(forty.bodies().back().position(), Vec3(0.0, 39.5, 0.0)), 0.05) << integratorName(integrator);
  }
}

// Bodies in contact are advanced by the solver, whatever integrator the scene names for free
// flight: a column in contact throughout ends bit for bit the same with each.
TEST(SoftStep, BodiesInContactDoNotDependOnTheFreeFlightIntegrator) {
  std::uint64_t reference = 0;
  for (Integrator integrator : allIntegrators()) {
    World world = boxes(settingsAt(kDt60, integrator), column(10));
    run(world, 2.0);
    if (integrator == allIntegrators().front()) reference = world.stateHash();
    EXPECT_EQ(world.stateHash(), reference) << integratorName(integrator);
  }
}

// The column sinks into itself by the contact springs' static deflection, F / (m_n omega^2) per
// contact under its load F (2.8 cm for 40 boxes at 120 Hz, the same at any dt), and stands.
TEST(SoftStep, ATallColumnStandsAtTwoHundredFortyHertz) {
  World world = boxes(settingsAt(kDt240), column(40));
  // 2 s under the sanitizers, hundreds of the 120 Hz contact springs' periods (5 s in the normal build).
  run(world, test::kSanitizedBuild ? 2.0 : 5.0);
  EXPECT_LT(horizontalDrift(world.bodies().back().position(), Vec3(0.0, 39.5, 0.0)), 0.01);
  EXPECT_LT(39.5 - world.bodies().back().position().y(), 0.03);
}

TEST(SoftStep, APyramidOfTwentyRowsStandsAtSixtyHertz) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "a 10 s outcome; the sanitizers see the same solver in the columns";
  const std::vector<Vec3> starts = pyramid(20);
  ASSERT_EQ(starts.size(), 210u);
  World world = boxes(settingsAt(kDt60), starts);
  run(world, 10.0);
  double worst = 0.0;
  for (std::size_t i = 0; i < starts.size(); ++i) worst = std::max(worst, (world.bodies()[i].position() - starts[i]).norm());
  EXPECT_LT(worst, 0.01) << "largest displacement of any box [m]";
}

// A heavy body on a light one, and a 1:10:100 column: the solver exchanges impulses between
// bodies of very different mass (the case Gauss-Seidel converges slowest on).
TEST(SoftStep, MassRatiosOfAHundredStand) {
  for (const std::vector<double>& masses : {std::vector<double>{1.0, 100.0}, std::vector<double>{1.0, 10.0, 100.0}}) {
    World world(settingsAt(kDt60));
    world.addPlane(Plane{}, softFriction(0.6));
    for (std::size_t i = 0; i < masses.size(); ++i) {
      world.addBody(test::boxWith(Vec3::Ones(), masses[i], Vec3(0.0, 0.5 + i, 0.0), softFriction(0.6), "box"));
    }
    run(world, 10.0);
    const double topStart = masses.size() - 0.5;
    const RigidBody& top = world.bodies().back();
    EXPECT_LT(horizontalDrift(top.position(), Vec3(0.0, topStart, 0.0)), 0.01) << masses.size() << " boxes";
    EXPECT_LT(std::abs(topStart - top.position().y()), 0.01) << masses.size() << " boxes";
    EXPECT_LT(top.velocity().norm(), 0.01);
  }
}

TEST(SoftStep, APlankOnTwoBoxesStands) {
  World world(settingsAt(kDt60));
  world.addPlane(Plane{}, softFriction(0.6));
  world.addBody(test::boxWith(Vec3::Ones(), 1.0, Vec3(-8.0, 0.5, 0.0), softFriction(0.6), "left"));
  world.addBody(test::boxWith(Vec3::Ones(), 1.0, Vec3(8.0, 0.5, 0.0), softFriction(0.6), "right"));
  world.addBody(test::boxWith(Vec3(20.0, 1.0, 20.0), 400.0, Vec3(0.0, 1.5, 0.0), softFriction(0.6), "plank"));
  const std::vector<Vec3> starts{Vec3(-8.0, 0.5, 0.0), Vec3(8.0, 0.5, 0.0), Vec3(0.0, 1.5, 0.0)};
  run(world, 10.0);
  // Each support carries 200 kg on its contact springs: the plank sinks 1.6 cm (F / (m_n
  // omega^2) at two contacts) and spreads its supports by 1-1.5 cm; nothing tips. The horizontal
  // drift is a random walk of the jitter at the 400:1 mass ratio: moving the plank's start by
  // 1e-12 to 1e-6 m gives 0.8 to 2.2 cm at 10 s, so the bound is 3 cm (the walk is issue 18's
  // known shortfall, not a tipping).
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EXPECT_LT(horizontalDrift(world.bodies()[i].position(), starts[i]), 0.03) << world.bodies()[i].name();
    EXPECT_LT(starts[i].y() - world.bodies()[i].position().y(), 0.02) << world.bodies()[i].name();
  }
}

// Apexes of a 0.3 m box dropped flat from 3 m onto a plane, both of restitution e and softFriction
// 0.6, measured from its lowest face: the seed's law u_N' = -e u_N gives apex ratios of e^2.
std::vector<double> apexes(double e, double dt, Integrator integrator, int count) {
  World world(settingsAt(dt, integrator));
  world.addPlane(Plane{}, softFriction(0.6, e));
  world.addBody(test::boxWith(Vec3::Constant(0.3), 1.0, Vec3(0.0, 3.15, 0.0), softFriction(0.6, e), "box"));
  const RigidBody& b = world.bodies()[0];
  std::vector<double> out{3.0};
  double previous = 0.0;
  while (static_cast<int>(out.size()) <= count && world.time() < 60.0) {
    world.step();
    const double vy = b.velocity().y();
    if (previous > 0.0 && vy <= 0.0) out.push_back(b.position().y() - 0.15);
    previous = vy;
  }
  return out;
}

// With integrators exact for constant gravity (rk4; dlm's half kicks are velocity Verlet),
// whatever free flight adds is nothing, so the apex shows what the contact does.
// At 1/240 s the apex holds to 0.1 % (3 mm) for ten bounces. At 1/60 s it rises up to 0.07 % a
// bounce (0.3-0.4 % by the seventh): for the steps it is within reach of the ground the solver
// integrates the box, with symplectic Euler over substeps, whose energy error is of order
// g (dt / substeps) |v|; and the one-sweep solve of each flat landing leaves a twist of about
// 0.2 rad/s, so that by the eighth bounce the box lands on an edge and tumbles (issue 18's
// closing note).
TEST(SoftStep, AnElasticBounceKeepsItsApexForTenBounces) {
  for (const auto& [dt, tolerance, bounces] : {std::tuple{kDt240, 0.003, 10}, std::tuple{kDt60, 0.015, 7}}) {
    const std::vector<double> a = apexes(1.0, dt, Integrator::Dlm, bounces);
    ASSERT_EQ(a.size(), static_cast<std::size_t>(bounces + 1)) << "dt " << dt;
    for (std::size_t k = 1; k < a.size(); ++k) EXPECT_NEAR(a[k], 3.0, tolerance) << "bounce " << k << ", dt " << dt;
  }
  const std::vector<double> a = apexes(1.0, kDt240, Integrator::Rk4, 10);
  for (std::size_t k = 1; k < a.size(); ++k) EXPECT_NEAR(a[k], 3.0, 0.003) << "rk4, bounce " << k;
}

TEST(SoftStep, BouncesKeepTheSquareOfTheRestitution) {
  for (double e : {0.3, 0.6, 0.9}) {
    for (double dt : {kDt60, kDt240}) {
      const std::vector<double> a = apexes(e, dt, Integrator::Dlm, 2);
      ASSERT_GE(a.size(), 3u);
      // Bounces whose apex is well above the distance a step moves the box (0.3 m): below,
      // an apex found as the step where v_y changes sign is off by up to |v| dt.
      for (std::size_t k = 1; k < a.size(); ++k) {
        if (a[k - 1] * e * e < 0.3) continue;
        EXPECT_NEAR(a[k] / a[k - 1], e * e, 0.02 * e * e) << "e " << e << ", dt " << dt << ", bounce " << k;
      }
    }
  }
}

// A ball dropped 1 m rebounds to e^2 h0 at 60 Hz as at 240 Hz. The collision pass reverses an
// approach at the start of the step that closes its gap, up to |v| dt above the ground, where
// the speed is a little lower, so the rebound may miss by up to (1 - e^2) |v| dt (plus the slop).
// Until the last relax let speculative points keep their approach, the step before the touch
// held the ball to the gap a substep closes: at 1/60 s it met the ground at 3.15 of 4.43 m/s
// and rose to 0.51 m for e = 1, 0.13 m for e = 0.5.
TEST(SoftStep, ABallReboundsToTheSquareOfTheRestitutionAt60Hz) {
  const double h0 = 1.0, radius = 0.1;
  const double impactSpeed = std::sqrt(2.0 * 9.81 * h0);
  for (double e : {0.5, 0.8, 1.0}) {
    for (double dt : {kDt60, kDt240}) {
      World world(settingsAt(dt, Integrator::Dlm));
      world.addPlane(Plane{}, softFriction(0.0, e));
      BodyDef def = shapeBodyDef(Shape::sphere(radius), 1.0, "ball");
      def.material = softFriction(0.0, e);
      def.position = Vec3(0.0, radius + h0, 0.0);
      world.addBody(def);
      const RigidBody& ball = world.bodies()[0];
      bool rising = false;
      double top = 0.0;
      while (world.time() < 2.5) {
        world.step();
        if (ball.velocity().y() > 0.0) rising = true;
        if (rising && ball.velocity().y() < 0.0) break;
        if (rising) top = std::max(top, ball.position().y() - radius);
      }
      const double slop = world.settings().contactSlop;
      EXPECT_NEAR(top, e * e * h0, (1.0 - e * e) * impactSpeed * dt + slop) << "e " << e << ", dt " << dt;
    }
  }
}

// Whatever the integrator adds or removes in free flight (forward Euler gains dt |v| of apex per
// flight), the step of the collision itself adds at most a quarter of one step's gravity work,
// m |g| |v| dt / 4 (1 % of this drop at 1/60 s). The gain is not the substeps' symplectic Euler
// error m |g| |v| dt / substeps alone: the worst over every integrator at both dt, in units of
// m |g| |v| dt, was 4.64 at 4 substeps, 0.125 at 8, 0.168 at 10 (the default since issue 34) and
// 0.022 at 16.
TEST(SoftStep, TheCollisionStepNeverAddsEnergyWithAnyIntegrator) {
  const double g = 9.81;
  for (Integrator integrator : allIntegrators()) {
    for (double dt : {kDt60, kDt240}) {
      World world(settingsAt(dt, integrator));
      world.addPlane(Plane{}, softFriction(0.6, 1.0));
      world.addBody(test::boxWith(Vec3::Constant(0.3), 1.0, Vec3(0.0, 3.15, 0.0), softFriction(0.6, 1.0), "box"));
      const RigidBody& b = world.bodies()[0];
      int collisions = 0;
      while (world.time() < 4.0) {
        const double before = b.kineticEnergy() + g * b.position().y();
        world.step();
        const bool hit = std::any_of(world.contactPoints().begin(), world.contactPoints().end(),
                                     [](const SolvedContactPoint& p) { return p.normalImpulse > 0.0; });
        if (!hit) continue;
        ++collisions;
        const double after = b.kineticEnergy() + g * b.position().y();
        const double bound = g * std::sqrt(2.0 * before) * dt / 4.0;  // m = 1 kg
        EXPECT_LE(after, before + bound) << integratorName(integrator) << ", dt " << dt << ", t " << world.time();
      }
      EXPECT_GT(collisions, 0) << integratorName(integrator);
    }
  }
}

// A body that never touches anything is advanced by its integrator exactly as without contacts.
TEST(SoftStep, FreeFlightIsTheIntegratorsAlone) {
  for (Integrator integrator : allIntegrators()) {
    Settings withGround = settingsAt(kDt60, integrator);
    Settings without = withGround;
    without.detectCollisions = false;
    World a(withGround), b(without);
    a.addPlane(Plane{Vec3::UnitY(), -100.0});
    for (World* w : {&a, &b}) {
      BodyDef def = test::boxWith(Vec3(1.0, 0.3, 0.1), 1.0, Vec3(0.0, 10.0, 0.0), Material{}, "tumbler");
      def.angularVelocity = Vec3(0.01, 10.0, 0.0);
      def.velocity = Vec3(1.0, 2.0, 0.0);
      w->addBody(def);
    }
    run(a, 2.0);
    run(b, 2.0);
    EXPECT_EQ(a.stateHash(), b.stateHash()) << integratorName(integrator);
  }
}

// Seed 001 "Resting Contact" after soft step: repulsive exactly (the clamp), and, once the box
// has landed (the second half of the run), the normal velocity of a pushing point within what
// one substep of gravity gives (g dt / substeps): one relax sweep per substep leaves a
// Gauss-Seidel residual of that order, where PGS's sweeps converge further
// (contact_solver_test.cpp). While it tumbles onto its edges one sweep leaves more: up to
// 0.32 m/s at one step of this run, on a corner pushed while its neighbour was being solved.
TEST(SoftStep, SolvedImpulsesSatisfySeed001sConditionsToOneSubstepOfGravity) {
  const Settings s = settingsAt(kDt240);
  const double tolerance = 9.81 * s.timeStep / s.substeps;
  World world(s);
  world.addPlane(Plane{});
  BodyDef box = test::boxWith(Vec3(1.0, 0.5, 0.7), 3.0, Vec3(0.0, 1.0, 0.0), Material{}, "box");
  box.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1.0, 0.3, 0.2).normalized()));
  box.angularVelocity = Vec3(1.0, 2.0, -1.0);
  world.addBody(box);
  int checked = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    for (const SolvedContactPoint& p : world.contactPoints()) {
      if (p.depth < 0.0) continue;
      EXPECT_GE(p.normalImpulse, 0.0) << "step " << i;
      if (i < 300) continue;
      EXPECT_GE(p.normalVelocity, -tolerance) << "step " << i;
      if (p.normalImpulse > 0.0) {
        EXPECT_LE(std::abs(p.normalVelocity), tolerance) << "step " << i;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 250);
}

// World::contactPoints() is built when first asked for after a step (soft_step_solver.h): it must
// be that step's, the same on every call and in a copy of the World, and empty once a body of the
// step is gone. A box at rest on the ground: the step's normal impulses carry its weight, m g dt.
TEST(SoftStep, ContactPointsAreTheLastStepsAndGoWithItsBodies) {
  for (double dt : {kDt60, kDt240}) {
    World world(settingsAt(dt));
    world.addPlane(Plane{}, softFriction(0.6));
    const double mass = 2.0;
    const BodyId box = world.addBody(test::boxWith(Vec3::Ones(), mass, Vec3(0.0, 0.5, 0.0), softFriction(0.6), "box"));
    const auto weightCarried = [&](const std::vector<SolvedContactPoint>& points) {
      double total = 0.0;
      for (const SolvedContactPoint& p : points) total += p.normalImpulse;
      return total / (mass * world.settings().gravity.norm() * dt);
    };
    for (int i = 0; i < 120; ++i) world.step();
    const std::vector<SolvedContactPoint> first = world.contactPoints();
    ASSERT_EQ(first.size(), 4u) << dt;
    EXPECT_NEAR(weightCarried(first), 1.0, 1e-6) << dt;
    const World copy = world;
    ASSERT_EQ(copy.contactPoints().size(), first.size());
    for (std::size_t k = 0; k < first.size(); ++k) {
      EXPECT_EQ(world.contactPoints()[k].normalImpulse, first[k].normalImpulse);
      EXPECT_EQ(copy.contactPoints()[k].normalImpulse, first[k].normalImpulse);
      EXPECT_EQ(copy.contactPoints()[k].position, first[k].position);
    }
    // Twice the weight for one step: the next step's points carry it, not the last step's.
    world.body(box).applyForce(Vec3(0.0, -mass * world.settings().gravity.norm(), 0.0));
    world.step();
    EXPECT_NEAR(weightCarried(world.contactPoints()), 2.0, 0.05) << dt;
    world.step();  // not asked for before the body goes
    world.destroyBody(box);
    EXPECT_TRUE(world.contactPoints().empty()) << dt;
  }
}

}  // namespace
}  // namespace rbsim
