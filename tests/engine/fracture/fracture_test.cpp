// Seed 000 "Fracture": pieces with v_i = v + omega x r_i and omega_i = omega keep the body's
// linear and angular momentum (and its kinetic energy: the motion is still rigid) to rounding.
#include "rbsim/fracture/fracture.h"

#include <gtest/gtest.h>

#include "fracture/pieces.h"
#include "rbsim/mass/mass_model.h"
#include "rbsim/math/rotation.h"

namespace rbsim {
namespace {

constexpr double kConservationTolerance = 1e-12;  // relative

struct Totals {
  double mass = 0.0;
  Vec3 linear = Vec3::Zero();   // sum m v [kg m/s]
  Vec3 angular = Vec3::Zero();  // about the world origin: sum (x x m v + L) [kg m^2/s]
  double energy = 0.0;          // [J]
};

Totals totalsOf(const std::vector<RigidBody>& bodies) {
  Totals t;
  for (const RigidBody& b : bodies) {
    t.mass += b.mass();
    t.linear += b.state().linearMomentum;
    t.angular += b.position().cross(b.state().linearMomentum) + b.state().angularMomentum;
    t.energy += b.kineticEnergy();
  }
  return t;
}

// A spinning, flying body of the given mesh with its exact inertia, and a pattern of `count`
// Voronoi pieces.
std::pair<BodyDef, FracturePattern> spinningBody(const Mesh& mesh, int count) {
  const MassModel model = buildMassModel(mesh, 3.0, std::nullopt, InertiaMethod::Exact);
  BodyDef def;
  def.name = "vase";
  def.mesh = model.mesh;
  def.mass = model.mass;
  def.inertiaBody = model.inertiaBody;
  def.position = Vec3(1.5, 2.0, -0.7);
  def.orientation = Quat(Eigen::AngleAxisd(0.9, Vec3(1.0, 2.0, 3.0).normalized()));
  def.velocity = Vec3(3.0, -1.0, 0.5);
  def.angularVelocity = Vec3(-2.0, 7.0, 1.5);
  FracturePattern pattern;
  pattern.impulseThreshold = 1.0;
  for (Mesh& piece : voronoiPieces(*model.mesh, sitesInside(*model.mesh, count, 42))) {
    pattern.pieces.push_back(std::make_shared<const Mesh>(std::move(piece)));
  }
  return {def, pattern};
}

Mesh slantedPrism() {  // a convex, asymmetric solid whose principal axes are not the mesh axes
  Mesh m;
  m.vertices = {{0.0, 0.0, 0.0}, {1.2, 0.1, 0.0}, {0.3, 0.9, 0.1}, {0.2, 0.1, 0.6}, {1.0, 0.8, 0.7}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 4}, {1, 4, 3}, {2, 3, 4}};
  return m;
}

void expectConserved(const Mesh& mesh, int count) {
  const auto [def, pattern] = spinningBody(mesh, count);
  ASSERT_EQ(checkFracturePattern(pattern, def), "");
  const RigidBody body(def);
  const Totals before = totalsOf({body});
  std::vector<RigidBody> pieces;
  for (const BodyDef& piece : fracturePieces(body, pattern, Material{})) pieces.emplace_back(piece);
  ASSERT_EQ(pieces.size(), pattern.pieces.size());
  const Totals after = totalsOf(pieces);
  EXPECT_NEAR(after.mass, before.mass, kConservationTolerance * before.mass);
  EXPECT_LT((after.linear - before.linear).norm(), kConservationTolerance * before.linear.norm());
  EXPECT_LT((after.angular - before.angular).norm(), kConservationTolerance * before.angular.norm());
  EXPECT_NEAR(after.energy, before.energy, kConservationTolerance * before.energy);
  for (const RigidBody& piece : pieces) {
    // omega_i = omega, up to the rounding of L_i = I_i omega and back.
    EXPECT_LT((piece.angularVelocity() - body.angularVelocity()).norm(), 1e-13 * body.angularVelocity().norm()) << piece.name();
    // The piece's centre moves as the body's point there did: v + omega x r_i.
    const Vec3 r = piece.position() - body.position();
    EXPECT_LT((piece.velocity() - body.velocity() - body.angularVelocity().cross(r)).norm(), 1e-13);
  }
}

TEST(Fracture, VoronoiPiecesOfABoxKeepMomentumAndEnergy) { expectConserved(makeBox(Vec3(0.4, 1.0, 0.25)), 12); }

TEST(Fracture, PiecesOfAnAsymmetricSolidKeepMomentumAndEnergy) { expectConserved(slantedPrism(), 9); }

TEST(Fracture, StaticBodyBreaksIntoPiecesAtRest) {
  auto [def, pattern] = spinningBody(makeBox(Vec3(2.0, 1.0, 0.2)), 5);
  def.isStatic = true;
  def.velocity = def.angularVelocity = Vec3::Zero();
  const RigidBody wall(def);
  double mass = 0.0;
  for (const BodyDef& piece : fracturePieces(wall, pattern, Material{})) {
    EXPECT_FALSE(piece.isStatic);
    EXPECT_EQ(piece.velocity, Vec3::Zero());
    EXPECT_EQ(piece.angularVelocity, Vec3::Zero());
    mass += piece.mass;
  }
  EXPECT_NEAR(mass, def.mass, 1e-12 * def.mass);
}

TEST(Fracture, PatternsThatCannotKeepMomentumAreRejected) {
  const Mesh prism = slantedPrism();
  auto [def, pattern] = spinningBody(prism, 4);
  EXPECT_EQ(checkFracturePattern(pattern, def), "");
  // The cube approximation's inertia is not the mesh's: angular momentum would change.
  BodyDef cube = def;
  cube.inertiaBody = buildMassModel(prism, 3.0, std::nullopt, InertiaMethod::Cube).inertiaBody;
  EXPECT_NE(checkFracturePattern(pattern, cube).find("exact"), std::string::npos);
  FracturePattern missing = pattern;
  missing.pieces.pop_back();  // no longer fills the body
  EXPECT_NE(checkFracturePattern(missing, def), "");
  FracturePattern one = pattern;
  one.pieces.resize(1);
  EXPECT_NE(checkFracturePattern(one, def), "");
  FracturePattern free = pattern;
  free.impulseThreshold = 0.0;
  EXPECT_NE(checkFracturePattern(free, def), "");
}

}  // namespace
}  // namespace rbsim
