// The exact reference contact solver (world.solver = "lcp", issue 55): the principal pivoting on
// problems with known answers, then seed 001 "Resting Contact"'s three conditions on every
// contact point of a resting stack and of a box on a slope, through the whole pipeline, to 1e-9
// of the step's velocity and impulse scales; the bodies stay at rest; a too large island is
// refused with a message; the scene key selects the solver.
#include "dynamics/lcp_solver.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics_util.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"

namespace rbsim {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Seed 001's conditions to 1e-9 (lcp_pivoting.h's tolerances are 1e-11 of the problem's scale).
constexpr double kExact = 1e-9;  // [1]
// At rest: speeds [m/s] and displacements over a second [m] of rounding's size (a hundred times
// the largest measured), where PGS's 10 sweeps leave about 1e-3 m/s.
constexpr double kAtRest = 1e-12;

// w = A f + b, f >= 0, w >= 0, f.w = 0, each to kExact of the scales of w and f.
void expectComplementary(const MatrixXd& a, const VectorXd& b, const LcpSolution& s, const std::string& what) {
  ASSERT_EQ(s.status, LcpSolution::Status::Solved) << what;
  const double wScale = std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  const double fScale = std::max(s.f.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LE((a * s.f + b - s.w).cwiseAbs().maxCoeff(), kExact * wScale) << what;
  for (Eigen::Index i = 0; i < b.size(); ++i) {
    EXPECT_GE(s.f(i), 0.0) << what << ", row " << i;
    EXPECT_GE(s.w(i), -kExact * wScale) << what << ", row " << i;
    EXPECT_LE(std::abs(s.f(i) * s.w(i)), kExact * fScale * wScale) << what << ", row " << i;
  }
}

TEST(LcpPivoting, SolvesRandomPositiveDefiniteProblems) {
  std::mt19937_64 random(55);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 40;
    MatrixXd g(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) g(i, j) = unit(random);
    }
    const MatrixXd a = g * g.transpose() + 1e-3 * MatrixXd::Identity(n, n);
    VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = unit(random);
    const LcpSolution s = solveLcp(a, b);
    expectComplementary(a, b, s, "trial " + std::to_string(trial));
    EXPECT_LE(s.pivots, 2 * n + 1) << "trial " << trial;
  }
}

// A = J J^T of rank k < n (more contact points than the bodies' freedoms, as four corners under a
// box), b made from a known solution with rows where both f and w are zero: solved, and w is the
// known one (lcp_pivoting.h: w is unique for a symmetric positive semidefinite A).
TEST(LcpPivoting, SolvesRedundantDegenerateProblems) {
  std::mt19937_64 random(1965);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 4 + trial % 36, k = 1 + trial % (n - 1);
    MatrixXd j(n, k);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < k; ++c) j(r, c) = unit(random);
    }
    const MatrixXd a = j * j.transpose();
    VectorXd f = VectorXd::Zero(n), w = VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) {
      const int kind = static_cast<int>(random() % 3);  // pushing, separating, or both zero
      if (kind == 0) f(i) = 1.0 + unit(random);
      if (kind == 1) w(i) = 1.0 + unit(random);
    }
    const VectorXd b = w - a * f;
    const LcpSolution s = solveLcp(a, b);
    expectComplementary(a, b, s, "trial " + std::to_string(trial));
    EXPECT_LE((s.w - w).cwiseAbs().maxCoeff(), kExact * b.cwiseAbs().maxCoeff()) << "trial " << trial;
  }
}

// A good guess is taken without pivoting; a wrong one still gives the solution.
TEST(LcpPivoting, AGuessedActiveSetSkipsThePivoting) {
  MatrixXd a(3, 3);
  a << 2.0, 1.0, 0.0, 1.0, 2.0, 1.0, 0.0, 1.0, 2.0;
  const VectorXd b(Eigen::Vector3d(-1.0, -1.0, 1.0));
  const LcpSolution first = solveLcp(a, b);
  expectComplementary(a, b, first, "cold");
  EXPECT_GT(first.pivots, 0);
  const LcpSolution again = solveLcp(a, b, &first.clamped);
  expectComplementary(a, b, again, "guessed");
  EXPECT_EQ(again.pivots, 0);
  const std::vector<char> wrong{0, 0, 1};
  expectComplementary(a, b, solveLcp(a, b, &wrong), "wrong guess");
}

// w1 + w2 = -2 whatever f: the driven point is stopped by nothing, reported instead of looping.
TEST(LcpPivoting, ReportsAProblemWithoutSolution) {
  MatrixXd a(2, 2);
  a << 1.0, -1.0, -1.0, 1.0;
  EXPECT_EQ(solveLcp(a, VectorXd::Constant(2, -1.0)).status, LcpSolution::Status::NoSolution);
}

Settings lcpSettings(double dt) {
  Settings s;
  s.solver = Settings::ContactSolverMethod::Lcp;
  s.timeStep = dt;
  s.allowSleep = false;  // the assertions are about the solver, not about sleeping hiding motion
  return s;
}

// Seed 001's three conditions at every point of the last step, at the velocity level of an
// impulse solver: w = u_rel,N - target >= 0 after the solve (the target is 0 at a touching point,
// -gap / dt at a speculative one, restitution being 0), j_N >= 0, j_N w = 0; to kExact of |g| dt
// and of the step's largest impulse. Returns the points checked.
int expectSeed001(const World& world, const std::string& what) {
  const double dt = world.settings().timeStep;
  const double uScale = world.settings().gravity.norm() * dt;
  double fScale = 0.0;
  for (const SolvedContactPoint& p : world.contactPoints()) fScale = std::max(fScale, p.normalImpulse);
  for (const SolvedContactPoint& p : world.contactPoints()) {
    const double w = p.normalVelocity - std::min(p.depth, 0.0) / dt;
    EXPECT_GE(w, -kExact * uScale) << what;
    EXPECT_GE(p.normalImpulse, 0.0) << what;
    EXPECT_LE(std::abs(p.normalImpulse * w), kExact * fScale * uScale) << what;
  }
  return static_cast<int>(world.contactPoints().size());
}

// The points of each manifold share its load equally: the least-norm solution (lcp_pivoting.h), which a
// symmetric face has, where the pivoting alone may put it on three corners or fewer.
void expectEqualCorners(const World& world, const std::string& what) {
  const std::vector<SolvedContactPoint>& points = world.contactPoints();
  for (std::size_t first = 0; first < points.size();) {
    std::size_t end = first;
    double least = points[first].normalImpulse, most = least;
    for (; end < points.size() && points[end].contact == points[first].contact; ++end) {
      least = std::min(least, points[end].normalImpulse);
      most = std::max(most, points[end].normalImpulse);
    }
    EXPECT_LE(most - least, kExact * most) << what << ", contact " << points[first].contact;
    first = end;
  }
}

// Steps for a second, checking seed 001 at every step; returns the fastest body's speed (linear,
// and angular times `radius`) over the second [m/s].
double restForASecond(World& world, double radius, const std::string& what, int minimumPoints,
                      bool equalCorners = false) {
  double fastest = 0.0;
  while (world.time() < 1.0 - 1e-9) {
    world.step();
    const std::string where = what + ", t = " + std::to_string(world.time());
    EXPECT_GE(expectSeed001(world, where), minimumPoints) << where;
    if (equalCorners) expectEqualCorners(world, where);
    for (const RigidBody& b : world.bodies()) {
      if (b.isDynamic()) fastest = std::max({fastest, b.velocity().norm(), radius * b.angularVelocity().norm()});
    }
  }
  return fastest;
}

TEST(LcpSolver, AResting4BoxStackMeetsSeed001sConditionsAndStaysAtRest) {
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    World world(lcpSettings(dt));
    world.addPlane(Plane{});
    const double size = 0.5;
    for (int i = 0; i < 4; ++i) {
      world.addBody(test::boxWith(Vec3(size, size, size), 1.0 + i, Vec3(0.0, (i + 0.5) * size, 0.0), Material{},
                                  "box" + std::to_string(i)));
    }
    const std::string what = "dt = 1/" + std::to_string(std::lround(1.0 / dt));
    // Four manifolds of four points. The velocity step ends at rest exactly (measured: 1e-14 m/s),
    // so nothing drifts or sinks (top box: 7e-16 m).
    EXPECT_LT(restForASecond(world, size, what, 16, true), kAtRest) << what << " [m/s]";
    EXPECT_NEAR(world.bodies().back().position().y(), 3.5 * size, kAtRest) << what;
  }
}

// A pyramid of 10 rows of unit boxes touching side by side (55 boxes, one island of 580 points,
// near kMaxLcpRows; A of rank well below that; many points touching with nothing to carry): the
// degenerate case the pivoting must not cycle on (lcp_pivoting.h, kLcpSchurTolerance; Lemke's
// method lost feasibility on a 400-point one). Seed 001 at every step of 10 (about a second), and
// at rest to where friction's passes stop at rounding (measured: 2e-11 m/s).
TEST(LcpSolver, AFiftyFiveBoxPyramidMeetsSeed001sConditionsAndStaysAtRest) {
  World world(lcpSettings(1.0 / 60.0));
  world.addPlane(Plane{});
  const int rows = 10;
  for (int r = 0; r < rows; ++r) {
    for (int i = 0; i < rows - r; ++i) {
      const Vec3 x(i - 0.5 * (rows - r - 1), 0.5 + r, 0.0);
      const std::string name = "b" + std::to_string(r) + "_" + std::to_string(i);
      world.addBody(test::boxWith(Vec3(1.0, 1.0, 1.0), 1.0, x, Material{}, name));
    }
  }
  double fastest = 0.0;
  for (int step = 0; step < 10; ++step) {
    world.step();
    expectSeed001(world, "step " + std::to_string(step));
    for (const RigidBody& b : world.bodies()) fastest = std::max(fastest, b.velocity().norm());
  }
  EXPECT_GE(world.contactPoints().size(), 500u);
  EXPECT_LT(fastest, 1e-9) << "[m/s]";
}

// A box at rest on a 20 degree slope (tan 20 = 0.36 < mu_s = 0.6): on a plane, and on a static
// tilted box (a body-body manifold with an infinite mass on one side).
TEST(LcpSolver, ABoxOnASlopeMeetsSeed001sConditionsAndStaysAtRest) {
  const double theta = 20.0 * kPi / 180.0;
  const Vec3 normal(-std::sin(theta), std::cos(theta), 0.0);
  const Quat tilt(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
  const Vec3 extents(0.4, 0.2, 0.4);
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    for (const bool onBox : {false, true}) {
      World world(lcpSettings(dt));
      if (onBox) {
        BodyDef ramp = test::boxWith(Vec3(4.0, 0.5, 4.0), 100.0, -0.25 * normal, Material{}, "ramp");
        ramp.orientation = tilt;
        ramp.isStatic = true;
        world.addBody(ramp);
      } else {
        world.addPlane(Plane{normal, 0.0});
      }
      BodyDef box = test::boxWith(extents, 1.0, 0.5 * extents.y() * normal, Material{}, "box");
      box.orientation = tilt;
      world.addBody(box);
      const std::string what = std::string(onBox ? "on a static box" : "on a plane") + ", dt = 1/" +
                               std::to_string(std::lround(1.0 / dt));
      const Vec3 start = world.bodies().back().position();
      // Measured: 3e-15 m/s, 1.5e-15 m moved.
      EXPECT_LT(restForASecond(world, 0.5 * extents.norm(), what, 4), kAtRest) << what << " [m/s]";
      EXPECT_LT((world.bodies().back().position() - start).norm(), kAtRest) << what << ": no creep [m]";
      // The friction block settles before its cap (measured: 32 passes from no friction, as every
      // step starts), so the rest above is not the cap's luck.
      std::vector<RigidBody> copy = world.bodies();
      const std::vector<Material> bodyMaterials(copy.size()), planeMaterials(world.planes().size());
      std::vector<Joint> joints;
      LcpSolver solver;
      IdTable<BodyId> ids;  // none removed: each body's key is its index
      for (std::size_t i = 0; i < copy.size(); ++i) ids.add();
      solver.solve({copy, world.contacts(), joints, ids, bodyMaterials, planeMaterials, world.settings()});
      EXPECT_LT(solver.lastFrictionPasses(), kMaxLcpFrictionPasses / 2) << what;
      // The normal impulses carry the weight's normal part, friction the rest (exactly, at rest).
      double normalSum = 0.0;
      for (const SolvedContactPoint& p : world.contactPoints()) normalSum += p.normalImpulse;
      EXPECT_NEAR(normalSum, 9.81 * std::cos(theta) * dt, 1e-9 * 9.81 * dt) << what;
    }
  }
}

// A box dropped tumbling onto the ground: seed 001's conditions at every step, through the impacts
// (restitution 0: every touching point's target is 0); it comes to rest on its face, no deeper
// than the slop plus one step's fall at the end.
TEST(LcpSolver, ATumblingBoxMeetsSeed001sConditionsAtEveryStepAndComesToRest) {
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    World world(lcpSettings(dt));
    world.addPlane(Plane{});
    BodyDef box = test::boxWith(Vec3(0.5, 0.3, 0.4), 2.0, Vec3(0.0, 1.0, 0.0), Material{}, "box");
    box.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1.0, 0.3, 0.2).normalized()));
    box.angularVelocity = Vec3(1.0, 2.0, -1.0);
    world.addBody(box);
    const std::string what = "dt = 1/" + std::to_string(std::lround(1.0 / dt));
    int points = 0;
    while (world.time() < 3.0 - 1e-9) {
      world.step();
      points += expectSeed001(world, what + ", t = " + std::to_string(world.time()));
    }
    EXPECT_GT(points, 100) << what;
    EXPECT_LT(world.bodies()[0].velocity().norm(), kAtRest) << what;
    EXPECT_GT(test::lowestVertexHeight(world.bodies()[0]), -world.settings().contactSlop - 9.81 * dt * dt) << what;
  }
}

// Weightless boxes meeting face to face, off centre, with friction: every point leaves at -c_R
// times its approach (seed 000; PGS meets it only to its sweeps' tolerance), and impulses equal and
// opposite at each point conserve P and x x P + L (the positions move with the velocities only:
// no split impulse without penetration).
TEST(LcpSolver, CollisionsReverseEveryPointExactlyAndConserveMomentum) {
  for (const double e : {0.5, 1.0}) {
    Settings s = lcpSettings(1.0 / 240.0);
    s.gravity = Vec3::Zero();
    World world(s);
    Material m;
    m.restitution = e;
    BodyDef a = test::boxWith(Vec3(1.0, 1.0, 1.0), 2.0, Vec3(-0.52, 0.0, 0.0), m, "a");
    BodyDef b = test::boxWith(Vec3(0.6, 0.8, 1.2), 1.0, Vec3(0.32, 0.3, 0.1), m, "b");
    a.velocity = Vec3(1.5, 0.0, 0.2);
    b.velocity = Vec3(-2.5, 0.3, 0.0);
    world.addBody(a);
    world.addBody(b);
    const Vec3 p = test::totalLinearMomentum(world), l = test::totalAngularMomentum(world);
    bool hit = false;
    for (int i = 0; i < 100 && !hit; ++i) {
      std::vector<double> before;
      const auto pointVelocity = [&](const Vec3& x, const RigidBody& body) -> Vec3 {
        return body.velocity() + body.angularVelocity().cross(x - body.position());
      };
      const std::vector<RigidBody> start = world.bodies();
      world.step();
      for (const SolvedContactPoint& q : world.contactPoints()) {
        if (q.normalImpulse <= 0.0) continue;
        hit = true;
        // Body 1 is b: the approach from the start of the step (no forces act), and after.
        const double approach = q.normal.dot(pointVelocity(q.position, start[1]) - pointVelocity(q.position, start[0]));
        EXPECT_NEAR(q.approachVelocity, approach, 1e-12) << "e = " << e;
        EXPECT_NEAR(q.normalVelocity, -e * approach, 1e-12 * std::abs(approach)) << "e = " << e;
      }
    }
    EXPECT_TRUE(hit) << "e = " << e;
    EXPECT_EQ(world.contactPoints().size(), 4u) << "e = " << e;
    EXPECT_TRUE(test::allNear(test::totalLinearMomentum(world), p, 1e-12)) << "e = " << e;
    EXPECT_TRUE(test::allNear(test::totalAngularMomentum(world), l, 1e-12)) << "e = " << e;
  }
}

// A column of 160 boxes is one island of about 640 points: refused at its first step with
// world.solver and the limit in the message, not solved for minutes.
TEST(LcpSolver, RefusesAnIslandBeyondItsRowLimit) {
  World world(lcpSettings(1.0 / 60.0));
  world.addPlane(Plane{});
  const int boxes = static_cast<int>(kMaxLcpRows / 4) + 10;
  for (int i = 0; i < boxes; ++i) {
    world.addBody(
        test::boxWith(Vec3(1.0, 1.0, 1.0), 1.0, Vec3(0.0, i + 0.5, 0.0), Material{}, "b" + std::to_string(i)));
  }
  try {
    world.step();
    ADD_FAILURE() << "an island of " << boxes << " boxes was solved";
  } catch (const SimulationError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("world.solver \"lcp\""), std::string::npos) << message;
    EXPECT_NE(message.find("kMaxLcpRows = " + std::to_string(kMaxLcpRows)), std::string::npos) << message;
  }
  // Boxes side by side on the ground are islands of four points each: any number is fine.
  World row(lcpSettings(1.0 / 60.0));
  row.addPlane(Plane{});
  for (int i = 0; i < boxes; ++i) {
    row.addBody(test::boxWith(Vec3(1.0, 1.0, 1.0), 1.0, Vec3(1.5 * i, 0.5, 0.0), Material{}, "b" + std::to_string(i)));
  }
  row.step();
  EXPECT_EQ(expectSeed001(row, "a row of boxes"), 4 * boxes);
}

TEST(LcpScene, TheSolverKeyTakesLcpAndRefusesWhatItCannotDo) {
  EXPECT_STREQ(contactSolverName(Settings::ContactSolverMethod::Lcp), "lcp");
  const std::string path = test::uniqueTempName("lcp_scene") + ".json";
  std::ofstream(path) << R"({"bodies": [{"name": "a", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1},
                                        {"name": "b", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1,
                                         "position": [2, 0, 0]}]})";
  const Scene scene = loadScene(path, {"world.solver=lcp"});
  EXPECT_EQ(scene.settings.solver, Settings::ContactSolverMethod::Lcp);
  const World world = buildWorld(scene);
  EXPECT_EQ(world.settings().solver, Settings::ContactSolverMethod::Lcp);
  const auto refused = [&](const std::vector<std::string>& overrides, const std::string& field,
                           const std::string& words) {
    try {
      loadScene(path, overrides);
      ADD_FAILURE() << overrides.back() << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(e.problem().find(words), std::string::npos) << e.what();
    }
  };
  refused({"world.solver=fast"}, "world.solver", "\"lcp\"");
  refused({"world.solver=lcp", "world.friction=seed000"}, "world.friction", "world.solver \"lcp\"");
  refused({"world.solver=lcp", R"(joints=[{"type": "ball", "body_a": "a", "body_b": "b", "anchor": [1, 0, 0]}])"},
          "joints[0].type", "LCP");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rbsim
