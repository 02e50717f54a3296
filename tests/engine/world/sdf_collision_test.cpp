// Bodies of any shape (seed 000 "Collision Detection": surface points against the other body's
// signed distance grid, and vice versa), through the whole World: resting places that the convex
// narrow phase gets wrong, and conservation in a collision of two non-convex bodies.
#include <gtest/gtest.h>

#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "geometry/surface_samples.h"
#include "rbsim/mass/mass_model.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

constexpr double kSdfDt = 1.0 / 240.0;  // [s]

BodyDef shapeDef(Mesh mesh, double mass, int resolution, const std::string& name) {
  const MassModel model = buildMassModel(std::move(mesh), mass, std::nullopt, InertiaMethod::Exact);
  BodyDef def;
  def.name = name;
  def.mesh = model.mesh;
  def.mass = model.mass;
  def.inertiaBody = model.inertiaBody;
  SdfGridOptions options;
  options.resolution = resolution;
  def.sdf = std::make_shared<const SignedDistanceGrid>(SignedDistanceGrid::build(*def.mesh, options));
  def.surfaceSamples = std::make_shared<const std::vector<Vec3>>(surfaceSamples(*def.mesh, def.sdf->cellSize()));
  return def;
}

// A static bowl of outer radius 1 m and wall 0.1 m, rim at y = 0: its cavity is the sphere of
// radius 0.9 m about the origin. Built from the mesh's own centre of mass, so placed to match.
constexpr double kBowlRadius = 1.0, kBowlWall = 0.1;  // [m]
std::size_t addBowl(World& world, int resolution) {
  Mesh bowl = makeBowl(kBowlRadius, kBowlWall, 48, 12);
  BodyDef def = shapeDef(bowl, 50.0, resolution, "bowl");
  const Vec3 centre = polyhedralMassProperties(bowl, 1.0).centerOfMass;
  def.position = centre;  // the mesh was re-centred on it: put the rim back at y = 0
  def.isStatic = true;
  return world.indexOf(world.addBody(def));
}

Settings sdfSettings() {
  Settings s;
  s.timeStep = kSdfDt;
  return s;
}

TEST(SdfCollision, ABoxComesToRestAtTheBottomOfABowl) {
  World world(sdfSettings());
  addBowl(world, 48);
  const double h = 0.15;  // half extent of the cube [m]
  BodyDef box = test::boxDef(Vec3::Constant(2.0 * h), 1.0);
  box.position = Vec3(0.02, 0.2, -0.01);
  world.addBody(box);
  for (int s = 0; s < 6 * 240; ++s) world.step();
  const RigidBody& b = world.bodies()[1];
  // Resting flat at the bottom, its four lower corners on the cavity sphere of radius 0.9 m:
  // centre height -sqrt(0.9^2 - 2 h^2) + h.
  const double cavity = kBowlRadius - kBowlWall;
  const double expectedY = -std::sqrt(cavity * cavity - 2.0 * h * h) + h;
  EXPECT_LT(b.velocity().norm(), 0.02);
  EXPECT_NEAR(b.position().y(), expectedY, 0.01);  // the contact slop and a fraction of a cell
  // Static friction (mu_s = 0.6 by default) holds it wherever the slope is below 31 degrees: it
  // stays near where it landed, never climbing the wall.
  EXPECT_LT(Vec2(b.position().x(), b.position().z()).norm(), 0.1);
}

TEST(SdfCollision, ATorusDropsOverAPostWhereItsHullWouldRestOnTop) {
  World world(sdfSettings());
  BodyDef post = test::boxDef(Vec3(0.1, 1.0, 0.1), 5.0, "post");
  post.position = Vec3(0.0, 0.5, 0.0);
  post.isStatic = true;
  world.addBody(post);
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  BodyDef ring = shapeDef(makeTorus(0.3, 0.08, 48, 24), 1.0, 40, "ring");
  ring.position = Vec3(0.0, 1.3, 0.0);  // its hole (0.22 m) around the post (0.07 m half diagonal)
  world.addBody(ring);
  for (int s = 0; s < 3 * 240; ++s) world.step();
  // It falls over the post to the ground: lying flat, its centre 0.08 m up.
  EXPECT_NEAR(world.bodies()[1].position().y(), 0.08, 0.01);
}

// Continuous collision sweeps bodies with a grid too (issue 36), as their convex hull: a torus
// thrown down at 40 m/s (0.67 m a step at 1/60 s) onto a 1 cm plate stops on it with both
// solvers. Without the sweep PGS (which integrates before it collides) leaves it stuck through
// the plate; the soft step's speculative contacts hold it either way.
TEST(SdfCollision, AFastTorusDoesNotTunnelThroughAThinPlate) {
  for (const auto solver : {Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs}) {
    for (const bool sweep : {true, false}) {
      Settings s = sdfSettings();
      s.timeStep = 1.0 / 60.0;
      s.solver = solver;
      s.continuousCollision = sweep;
      World world(s);
      BodyDef plate = test::boxDef(Vec3(2.0, 0.01, 2.0), 5.0, "plate");
      plate.isStatic = true;
      world.addBody(plate);
      BodyDef ring = shapeDef(makeTorus(0.3, 0.08, 32, 16), 1.0, 32, "ring");
      ring.position = Vec3(0.0, 1.0, 0.0);
      ring.velocity = Vec3(0.0, -40.0, 0.0);
      const BodyId id = world.addBody(ring);
      for (int step = 0; step < 60; ++step) world.step();
      const double y = world.body(id).position().y();
      const std::string which = std::string(solver == Settings::ContactSolverMethod::Pgs ? "pgs" : "soft step") +
                                (sweep ? ", swept" : ", not swept");
      if (sweep) {
        EXPECT_GT(y, 0.0) << which << ": it went through the plate";
      } else if (solver == Settings::ContactSolverMethod::Pgs) {
        EXPECT_LT(y, 0.0) << which << ": the test's torus must go into the plate without the sweep";
      }
    }
  }
}

TEST(SdfCollision, TwoToriCollidingKeepMomentum) {
  Settings s = sdfSettings();
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef a = shapeDef(makeTorus(0.3, 0.1, 32, 16), 1.0, 32, "a");
  BodyDef b = shapeDef(makeTorus(0.3, 0.1, 32, 16), 2.0, 32, "b");
  a.position = Vec3(-0.8, 0.05, 0.0);
  a.velocity = Vec3(2.0, 0.0, 0.3);
  a.angularVelocity = Vec3(0.0, 0.0, 3.0);
  b.position = Vec3(0.3, 0.0, 0.0);
  b.orientation = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()));  // linked-ring pose: b stands up
  world.addBody(a);
  world.addBody(b);
  auto momentum = [&world] {
    return Vec3(world.bodies()[0].state().linearMomentum + world.bodies()[1].state().linearMomentum);
  };
  const Vec3 before = momentum();
  bool touched = false;
  for (int k = 0; k < 240; ++k) {
    world.step();
    touched = touched || !world.contacts().empty();
  }
  ASSERT_TRUE(touched);
  EXPECT_LT((momentum() - before).norm(), 1e-12 * before.norm());
  EXPECT_GT(world.bodies()[1].velocity().x(), 0.0) << "b was pushed along +x";
}

}  // namespace
}  // namespace rbsim
