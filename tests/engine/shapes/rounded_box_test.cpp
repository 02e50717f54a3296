// The rounded box (shapes/shape.h Shape::roundedBox), added by following docs/architecture.md
// ("Adding things: a shape"): its exact queries against their definitions, its closed-form mass
// properties against a capsule, a ball and the polyhedral integrals of a fine mesh, its display
// mesh on the surface, and bodies of it resting on the ground, on each other and under a ball, at
// dt = 1/60 s and 1/240 s with both contact solvers.
#include <cmath>
#include <map>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/io/input_error.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/rotation.h"
#include "rbsim/scene/scene.h"
#include "rbsim/shapes/shape.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

const Vec3 kCore(0.3, 0.1, 0.2);  // [m]
constexpr double kRadius = 0.05;  // [m]

Vec3 roundedRandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

TEST(RoundedBox, SupportAndBoundsAreTheCoreGrownByTheRadius) {
  const Shape s = Shape::roundedBox(kCore, kRadius);
  EXPECT_TRUE(s.isRound());
  EXPECT_STREQ(shapeTypeName(s.type), "rounded box");
  std::mt19937 rng(5);
  for (int i = 0; i < 200; ++i) {
    const Vec3 u = roundedRandomUnit(rng);
    // The extent along a unit u of a box grown by r: |u| . h + r.
    EXPECT_NEAR(u.dot(s.support(2.0 * u)), u.cwiseAbs().dot(kCore) + kRadius, 1e-15);
    const Mat3 R = rotationFromAxisAngle(roundedRandomUnit(rng) * 2.0);
    const Vec3 x(1.0, -2.0, 0.5);
    const auto [lo, hi] = s.worldBounds(R, x);
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k);
      EXPECT_NEAR(hi[k], (R * s.support(R.transpose() * e) + x)[k], 1e-12);
      EXPECT_NEAR(lo[k], (R * s.support(-R.transpose() * e) + x)[k], 1e-12);
    }
  }
  EXPECT_NEAR(s.boundingRadius(), kCore.norm() + kRadius, 1e-15);
}

TEST(RoundedBox, RoundDistanceIsTheDistanceToTheSurface) {
  const Shape s = Shape::roundedBox(kCore, kRadius);
  auto [d, n] = s.roundDistance(Vec3(1.0, 0.0, 0.0));  // beyond the +x face
  EXPECT_NEAR(d, 1.0 - 0.3 - kRadius, 1e-15);
  EXPECT_EQ(n, Vec3::UnitX());
  std::tie(d, n) = s.roundDistance(Vec3(0.4, 0.2, 0.0));  // beside the edge x = 0.3, y = 0.1
  EXPECT_NEAR(d, std::sqrt(0.02) - kRadius, 1e-15);
  EXPECT_TRUE(n.isApprox(Vec3(1.0, 1.0, 0.0).normalized(), 1e-15));
  std::tie(d, n) = s.roundDistance(Vec3(0.1, 0.05, 0.0));  // inside the core: the nearest face is y
  EXPECT_NEAR(d, -(0.1 - 0.05) - kRadius, 1e-15);
  EXPECT_EQ(n, Vec3::UnitY());
  EXPECT_THROW(Shape::roundedBox(Vec3(0.1, -0.1, 0.1), 0.1), std::invalid_argument);
  EXPECT_THROW(Shape::roundedBox(kCore, 0.0), std::invalid_argument);
}

// Three independent checks: a rounded box with a point core is a ball and with a segment core a
// capsule (both exactly, shape.cpp's other closed forms); a general one against the polyhedral
// integrals (Mirtich) of its fine display mesh, which is inscribed and converges as h^2.
TEST(RoundedBox, MassPropertiesMatchTheBallTheCapsuleAndAFineMesh) {
  const Shape ball = Shape::roundedBox(Vec3::Zero(), 0.5);
  EXPECT_NEAR(roundOrBoxVolume(ball), roundOrBoxVolume(Shape::sphere(0.5)), 1e-15);
  EXPECT_TRUE(roundOrBoxInertia(ball, 2.0).isApprox(roundOrBoxInertia(Shape::sphere(0.5), 2.0), 1e-14));
  const Shape capsule = Shape::roundedBox(Vec3(0.0, 0.3, 0.0), 0.2);  // a segment along y
  EXPECT_NEAR(roundOrBoxVolume(capsule), roundOrBoxVolume(Shape::capsule(0.2, 0.3)), 1e-15);
  EXPECT_TRUE(roundOrBoxInertia(capsule, 3.0).isApprox(roundOrBoxInertia(Shape::capsule(0.2, 0.3), 3.0), 1e-14));
  const Shape box = Shape::roundedBox(kCore, kRadius);
  const MassProperties fine = polyhedralMassProperties(makeRoundedBox(kCore, kRadius, 64), 1000.0);
  const double volume = roundOrBoxVolume(box);
  EXPECT_NEAR(fine.volume / volume, 1.0, 1e-4);
  const Mat3 exact = roundOrBoxInertia(box, 1000.0 * volume);
  EXPECT_LT((fine.inertia - exact).norm() / exact.norm(), 2e-4);
  EXPECT_LT(fine.centerOfMass.norm(), 1e-12);
  // As the radius goes to 0 it is the box.
  const Shape sharp = Shape::roundedBox(kCore, 1e-9);
  EXPECT_TRUE(roundOrBoxInertia(sharp, 1.0).isApprox(roundOrBoxInertia(Shape::box(kCore), 1.0), 1e-7));
}

TEST(RoundedBox, TheDisplayMeshIsClosedAndOnTheSurface) {
  const Shape s = Shape::roundedBox(kCore, kRadius);
  const Mesh mesh = displayMeshOf(s);
  for (const Vec3& p : mesh.vertices) EXPECT_NEAR(s.roundDistance(p).first, 0.0, 1e-15);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;  // directed: each once, and its reverse once
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  }
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
  const MassProperties m = polyhedralMassProperties(mesh, 1.0);
  EXPECT_GT(m.volume, 0.99 * roundOrBoxVolume(s));  // outward, and inscribed
  EXPECT_LT(m.volume, roundOrBoxVolume(s));
}

using Solver = Settings::ContactSolverMethod;
struct Case {
  double dt;
  Solver solver;
};

class RoundedBoxBodies : public testing::TestWithParam<Case> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam().dt;
    s.solver = GetParam().solver;
    // PGS integrates before it solves, tuned with expmap's drift (round_bodies_test.cpp).
    if (s.solver == Solver::Pgs) s.integrator = Integrator::ExpMap;
    s.allowSleep = false;  // the figures are the solver's, not the sleep's
    return s;
  }
  int steps(double seconds) const { return static_cast<int>(std::lround(seconds / GetParam().dt)); }
  static BodyDef roundedBox(const Vec3& position, const std::string& name) {
    BodyDef def = shapeBodyDef(Shape::roundedBox(kCore, kRadius), 2.0, name);
    def.position = position;
    return def;
  }
};

// Dropped flat from 5 cm, it settles on its flat bottom face: four points (the core's bottom
// corners), its centre at h_y + r above the ground within the solvers' slop, level and still.
TEST_P(RoundedBoxBodies, RestsFlatOnTheGround) {
  World w(settings());
  w.addPlane(Plane{});
  w.addBody(roundedBox(Vec3(0.0, 0.2, 0.0), "slab"));
  for (int i = 0; i < steps(2.0); ++i) w.step();
  const RigidBody& b = w.bodies()[0];
  EXPECT_NEAR(b.position().y(), kCore.y() + kRadius, 0.006);
  EXPECT_GT(b.rotation().col(1).y(), 1.0 - 1e-9);  // level
  EXPECT_LT(b.velocity().norm() + b.angularVelocity().norm(), 1e-3);
  ASSERT_EQ(w.contacts().size(), 1u);
  EXPECT_EQ(w.contacts()[0].manifold.count, 4);
}

// Three stacked, each 0.3 m tall: they stand, each on the one below, face on face. Dropped 1 cm
// apart, they shift sideways by at most 1.0 mm in 3 s (soft step, 1/60 s); plain boxes of the
// same outer size measured 1.6 mm (0.45 mm with PGS), so the bound is the boxes' own.
TEST_P(RoundedBoxBodies, AStackOfThreeStands) {
  World w(settings());
  w.addPlane(Plane{});
  const double height = 2.0 * (kCore.y() + kRadius);
  for (int i = 0; i < 3; ++i) w.addBody(roundedBox(Vec3(0.0, (i + 0.5) * height + 0.01 * i, 0.0), "b" + std::to_string(i)));
  for (int i = 0; i < steps(3.0); ++i) w.step();
  for (int i = 0; i < 3; ++i) {
    const RigidBody& b = w.bodies()[static_cast<std::size_t>(i)];
    EXPECT_NEAR(b.position().y(), (i + 0.5) * height, 0.006 * (i + 1)) << i;
    EXPECT_LT(std::hypot(b.position().x(), b.position().z()), 2e-3) << i;
    EXPECT_LT(b.velocity().norm(), 1e-3) << i;
  }
  for (const Contact& c : w.contacts()) EXPECT_EQ(c.manifold.count, 4);
}

// A ball set on its top face, off centre, rests there: the face is flat, so nothing rolls it.
TEST_P(RoundedBoxBodies, ABallRestsOnItsTopFace) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef base = roundedBox(Vec3(0.0, kCore.y() + kRadius, 0.0), "base");
  base.isStatic = true;
  w.addBody(base);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.1), 0.5, "ball");
  ball.position = Vec3(0.15, 2.0 * (kCore.y() + kRadius) + 0.1, 0.05);
  w.addBody(ball);
  for (int i = 0; i < steps(2.0); ++i) w.step();
  const RigidBody& b = w.bodies()[1];
  EXPECT_NEAR(b.position().y(), 2.0 * (kCore.y() + kRadius) + 0.1, 0.006);
  EXPECT_NEAR(b.position().x(), 0.15, 1e-6);
  EXPECT_NEAR(b.position().z(), 0.05, 1e-6);
  EXPECT_LT(b.velocity().norm(), 1e-3);
}

// Tipped onto an edge, it falls and comes to rest flat: the round edge rolls it down, no corner
// catches.
TEST_P(RoundedBoxBodies, ReleasedOnAnEdgeItFallsFlat) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef def = roundedBox(Vec3(0.0, 0.3, 0.0), "tipped");
  def.orientation = quatFromAxisAngle(Vec3(0.0, 0.0, 0.3));
  w.addBody(def);
  for (int i = 0; i < steps(4.0); ++i) w.step();
  const RigidBody& b = w.bodies()[0];
  EXPECT_NEAR(b.position().y(), kCore.y() + kRadius, 0.006);
  EXPECT_GT(b.rotation().col(1).y(), 1.0 - 1e-6);
  EXPECT_LT(b.velocity().norm() + b.angularVelocity().norm(), 1e-3);
}

// At the edge of the scene's range, radius = half the smallest extent, the core is flat (or 1 mm
// thin): all eight core corners are within the margin of the ground. The manifold must keep the
// four that span the face, not the first four (one edge), or the slab tips and sinks through the
// ground (y fell to 0.002 m in 2 s before). Two such slabs stack.
TEST_P(RoundedBoxBodies, AFlatCoreRestsFlatAndStacks) {
  for (const double thickness : {0.0, 1e-3}) {  // the core's half height [m]
    const Shape slab = Shape::roundedBox(Vec3(0.2, thickness, 0.1), 0.1);
    World w(settings());
    w.addPlane(Plane{});
    const double half = thickness + 0.1;
    for (int i = 0; i < 2; ++i) {
      BodyDef def = shapeBodyDef(slab, 1.0, "slab" + std::to_string(i));
      def.position = Vec3(0.0, (2 * i + 1) * half + 0.01 * i, 0.0);
      def.orientation = quatFromAxisAngle(Vec3(0.0, 0.3 * i, 0.0));  // the top one turned about y
      w.addBody(def);
    }
    for (int i = 0; i < steps(2.0); ++i) w.step();
    for (int i = 0; i < 2; ++i) {
      const RigidBody& b = w.bodies()[static_cast<std::size_t>(i)];
      EXPECT_NEAR(b.position().y(), (2 * i + 1) * half, 0.006) << thickness << " " << i;
      EXPECT_GT(b.rotation().col(1).y(), 1.0 - 1e-6) << thickness << " " << i;
      EXPECT_LT(b.velocity().norm(), 1e-3) << thickness << " " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(DtAndSolver, RoundedBoxBodies,
                         testing::Values(Case{1.0 / 60.0, Solver::SoftStep}, Case{1.0 / 240.0, Solver::SoftStep},
                                         Case{1.0 / 60.0, Solver::Pgs}, Case{1.0 / 240.0, Solver::Pgs}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.solver == Solver::Pgs ? "Pgs" : "SoftStep") +
                                  (info.param.dt > 0.01 ? "_60Hz" : "_240Hz");
                         });

TEST(RoundedBoxScene, ReadsItsKeysAndRefusesARadiusTooLarge) {
  const std::string ok = R"({"world": {"dt": 0.01}, "bodies": [{"name": "r", "mass": 1,
      "shape": {"type": "rounded_box", "extents": [0.7, 0.3, 0.5], "radius": 0.05}}]})";
  const Scene scene = parseSceneText(ok, "rounded.json", "");
  ASSERT_TRUE(scene.bodies[0].shape.has_value());
  EXPECT_EQ(scene.bodies[0].shape->type, ShapeType::RoundedBox);
  EXPECT_TRUE(scene.bodies[0].shape->halfExtents.isApprox(kCore, 1e-15));
  EXPECT_EQ(scene.bodies[0].shape->radius, kRadius);
  const std::string bad = R"({"world": {"dt": 0.01}, "bodies": [{"name": "r", "mass": 1,
      "shape": {"type": "rounded_box", "extents": [0.7, 0.3, 0.5], "radius": 0.2}}]})";
  try {
    parseSceneText(bad, "rounded.json", "");
    FAIL() << "a radius over half the smallest extent must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(e.field().find("radius"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("half the smallest extent"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbsim
