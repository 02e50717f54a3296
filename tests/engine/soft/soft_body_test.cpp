// soft/soft_body: seed 002's finite-volume forces on tetrahedra (f_i = P b_i), and the physics
// they must give: forces summing to zero, forces as the negative energy gradient, no force under
// rigid motion, a bar stretching by F L / (E A) and contracting by nu, bounded energy of an
// undamped oscillation, the explicit step's stability limit, momentum kept in free flight, and
// a block resting on the ground.
#include "rbsim/soft/soft_body.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "../../sanitized_build.h"

namespace rbsim {
namespace {

const ConstitutiveModel kSoftBodyModels[] = {ConstitutiveModel::Linear, ConstitutiveModel::StVenantKirchhoff,
                                     ConstitutiveModel::Corotated, ConstitutiveModel::NeoHookean};

SoftBodyDef block(ConstitutiveModel model, int cells = 2) {
  SoftBodyDef def;
  def.mesh = makeTetBox(Vec3(1.0, 1.0, 1.0), cells, cells, cells);
  def.model = model;
  def.youngsModulus = 1e5;
  def.poissonRatio = 0.3;
  def.density = 1000.0;
  return def;
}

void perturb(SoftBody& body, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-size, size);
  for (Vec3& x : body.positions()) x += Vec3(u(rng), u(rng), u(rng));
}

TEST(TetMesh, BoxIsConformingWithAClosedOutwardBoundary) {
  const TetMesh mesh = makeTetBox(Vec3(2.0, 1.0, 1.0), 4, 2, 3);
  EXPECT_EQ(mesh.nodes.size(), 5u * 3u * 4u);
  EXPECT_EQ(mesh.tets.size(), 6u * 4u * 2u * 3u);
  EXPECT_TRUE(checkTetMesh(mesh).empty());
  // Two triangles per boundary square, 2 (4*2 + 4*3 + 2*3) squares, enclosing the box's volume.
  EXPECT_EQ(mesh.boundary.size(), 2u * 2u * (8u + 12u + 6u));
  double volume = 0.0;
  for (const auto& f : mesh.boundary) volume += mesh.nodes[f[0]].dot(mesh.nodes[f[1]].cross(mesh.nodes[f[2]])) / 6.0;
  EXPECT_NEAR(volume, 2.0, 1e-12);
}

TEST(SoftBody, AreaWeightedNormalsAreSeed002sFaceSums) {
  SoftBodyDef def = block(ConstitutiveModel::Corotated, 1);
  def.mesh.nodes[7] += Vec3(0.1, -0.05, 0.2);  // a skewed rest shape
  const SoftBody body(def);
  for (std::size_t t = 0; t < body.tetCount(); ++t) {
    const Tet& tet = body.mesh().tets[t];
    const Mat3& b = body.areaWeightedNormals(t);
    for (int i = 1; i < 4; ++i) {
      // -1/3 of the sum of A_j N_j (outward, material frame) over the three faces at node i.
      Vec3 sum = Vec3::Zero();
      for (int skip = 0; skip < 4; ++skip) {
        if (skip == i) continue;
        int f[3], k = 0;
        for (int c = 0; c < 4; ++c) {
          if (c != skip) f[k++] = c;
        }
        const Vec3 a = body.mesh().nodes[tet[f[0]]], bb = body.mesh().nodes[tet[f[1]]], c = body.mesh().nodes[tet[f[2]]];
        Vec3 areaNormal = 0.5 * (bb - a).cross(c - a);
        if (areaNormal.dot(body.mesh().nodes[tet[skip]] - a) > 0.0) areaNormal = -areaNormal;
        sum += areaNormal;
      }
      EXPECT_LT((b.col(i - 1) - (-sum / 3.0)).norm(), 1e-14) << "tet " << t << " node " << i;
    }
  }
}

TEST(SoftBody, ForcesSumToZeroWithoutTorqueAndAreTheNegativeEnergyGradient) {
  for (ConstitutiveModel model : kSoftBodyModels) {
    SoftBody body(block(model));
    perturb(body, 0.05, 3);
    std::vector<Vec3> forces;
    body.internalForces(forces);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
    double largest = 0.0;
    for (std::size_t i = 0; i < forces.size(); ++i) {
      total += forces[i];
      torque += body.positions()[i].cross(forces[i]);
      largest = std::max(largest, forces[i].norm());
    }
    ASSERT_GT(largest, 1.0) << constitutiveModelName(model);
    EXPECT_LT(total.norm(), 1e-10 * largest) << constitutiveModelName(model);
    if (model != ConstitutiveModel::Linear) {
      EXPECT_LT(torque.norm(), 1e-10 * largest) << constitutiveModelName(model);
    }
    const double h = 1e-7;
    for (std::size_t i : {0u, 5u, 13u, 26u}) {
      for (int axis = 0; axis < 3; ++axis) {
        SoftBody plus = body, minus = body;
        plus.positions()[i][axis] += h;
        minus.positions()[i][axis] -= h;
        const double gradient = (plus.elasticEnergy() - minus.elasticEnergy()) / (2.0 * h);
        EXPECT_NEAR(forces[i][axis], -gradient, 1e-5 * largest) << constitutiveModelName(model) << " node " << i;
      }
    }
  }
}

TEST(SoftBody, NoForceAtRestOrAfterARigidMotionExceptLinear) {
  const Mat3 R = rotationFromAxisAngle(0.9 * Vec3(0.3, 1.0, -0.2).normalized());
  for (ConstitutiveModel model : kSoftBodyModels) {
    SoftBody body(block(model));
    std::vector<Vec3> forces;
    body.internalForces(forces);
    for (const Vec3& f : forces) EXPECT_LT(f.norm(), 1e-9) << constitutiveModelName(model);
    for (Vec3& x : body.positions()) x = R * x + Vec3(3.0, -1.0, 2.0);
    body.internalForces(forces);
    double largest = 0.0;
    for (const Vec3& f : forces) largest = std::max(largest, f.norm());
    if (model == ConstitutiveModel::Linear) {
      EXPECT_GT(largest, 1e3) << "Cauchy strain sees the rotation";
    } else {
      EXPECT_LT(largest, 1e-6) << constitutiveModelName(model);
    }
  }
}

// A free bar pulled at both ends by a uniform traction: uniaxial stress s = F / A everywhere, so
// the exact static solution (linear displacement) is one the linear tetrahedra represent exactly.
TEST(SoftBody, BarUnderUniaxialLoadStretchesByFLOverEAAndContractsByNu) {
  const double length = 2.0, side = 0.2, E = 1e6, nu = 0.3, load = 20.0;  // [m], [m], [Pa], [1], [N]
  SoftBodyDef def;
  // Linear tetrahedra hold the exact (linear) solution on any mesh: the sanitizers take a coarser
  // one (the normal build keeps 10 x 2 x 2 cells).
  def.mesh = test::kSanitizedBuild ? makeTetBox(Vec3(length, side, side), 5, 1, 1) : makeTetBox(Vec3(length, side, side), 10, 2, 2);
  def.model = ConstitutiveModel::Linear;
  def.youngsModulus = E;
  def.poissonRatio = nu;
  def.density = 100.0;
  def.damping = 2e4;
  SoftBody bar(def);
  // Consistent nodal loads: each end triangle gives a third of traction times area to its nodes.
  std::vector<Vec3> external(bar.positions().size(), Vec3::Zero());
  for (const auto& f : bar.mesh().boundary) {
    const Vec3 a = bar.mesh().nodes[f[0]], b = bar.mesh().nodes[f[1]], c = bar.mesh().nodes[f[2]];
    const Vec3 areaNormal = 0.5 * (b - a).cross(c - a);
    if (std::abs(std::abs(areaNormal.normalized().x()) - 1.0) > 1e-12) continue;
    const Vec3 share = (load / (side * side)) * areaNormal.norm() / 3.0 * Vec3(areaNormal.x() > 0.0 ? 1.0 : -1.0, 0.0, 0.0);
    for (std::uint32_t n : f) external[n] += share;
  }
  // Static equilibrium by damped backward Euler: external loads act as a constant "gravity" per
  // node, a = F_ext / m.
  for (int step = 0; step < 400; ++step) {
    for (std::size_t i = 0; i < external.size(); ++i) bar.velocities()[i] += 0.01 * external[i] / bar.nodeMasses()[i];
    bar.step(0.01, Vec3::Zero(), {}, {});
  }
  double right = 0.0, left = 0.0, top = 0.0, bottom = 0.0;
  int rightCount = 0, leftCount = 0, topCount = 0, bottomCount = 0;
  for (std::size_t i = 0; i < external.size(); ++i) {
    const Vec3& rest = bar.mesh().nodes[i];
    const Vec3& now = bar.positions()[i];
    if (rest.x() > 0.5 * length - 1e-9) right += now.x(), ++rightCount;
    if (rest.x() < -0.5 * length + 1e-9) left += now.x(), ++leftCount;
    if (rest.y() > 0.5 * side - 1e-9) top += now.y(), ++topCount;
    if (rest.y() < -0.5 * side + 1e-9) bottom += now.y(), ++bottomCount;
  }
  const double stretch = right / rightCount - left / leftCount - length;
  const double width = top / topCount - bottom / bottomCount;
  const double expected = load * length / (E * side * side);
  EXPECT_NEAR(stretch, expected, 1e-3 * expected) << "F L / (E A)";
  EXPECT_NEAR((width - side) / side, -nu * expected / length, 1e-3 * nu * expected / length) << "lateral strain -nu eps";
}

// Symplectic Euler keeps a nearby energy: the total oscillates by an amount that shrinks with dt
// and does not grow, below the stability estimate; five times the estimate blows up.
TEST(SoftBody, UndampedOscillationKeepsItsEnergyBoundedBelowTheStableStep) {
  // A third of the run under the sanitizers, still many periods at either step (6000 steps in
  // the normal build).
  const int kOscillationSteps = test::kSanitizedBuild ? 2000 : 6000;
  SoftBodyDef def = block(ConstitutiveModel::Corotated, 3);
  def.integrator = SoftIntegrator::SymplecticEuler;
  for (const auto& [factor, band] : {std::pair{0.1, 0.05}, std::pair{0.9, 0.35}}) {
    SoftBody body(def);
    perturb(body, 0.03, 5);
    const double dt = factor * body.stableTimeStep();
    const double initial = body.elasticEnergy() + body.kineticEnergy();
    double lowest = initial, highest = initial, highestEarly = initial, highestLate = 0.0;
    for (int step = 0; step < kOscillationSteps; ++step) {
      body.step(dt, Vec3::Zero(), {}, {});
      const double energy = body.elasticEnergy() + body.kineticEnergy();
      lowest = std::min(lowest, energy);
      highest = std::max(highest, energy);
      const bool early = step < kOscillationSteps / 2;
      (early ? highestEarly : highestLate) = std::max(early ? highestEarly : highestLate, energy);
    }
    EXPECT_LT(highest, (1.0 + band) * initial) << factor << " of the stable step";
    EXPECT_GT(lowest, (1.0 - band) * initial) << factor << " of the stable step";
    EXPECT_LE(highestLate, highestEarly) << "no growth at " << factor << " of the stable step";
  }
  SoftBody fast(def);
  perturb(fast, 0.03, 5);
  const double initial = fast.elasticEnergy();
  EXPECT_THROW(
      {
        for (int step = 0; step < 3000; ++step) {
          fast.step(5.0 * fast.stableTimeStep(), Vec3::Zero(), {}, {});
          if (fast.elasticEnergy() > 1e6 * initial) throw std::domain_error("energy grew a million-fold");
        }
      },
      std::domain_error);
}

TEST(SoftBody, FreeFlightKeepsMomentumWithBothIntegrators) {
  for (SoftIntegrator integrator : {SoftIntegrator::SymplecticEuler, SoftIntegrator::BackwardEuler}) {
    SoftBodyDef def = block(ConstitutiveModel::NeoHookean);
    def.integrator = integrator;
    def.damping = 5.0;
    def.velocity = Vec3(1.0, 2.0, -0.5);
    SoftBody body(def);
    perturb(body, 0.04, 9);
    const Vec3 before = body.linearMomentum();
    for (int step = 0; step < 200; ++step) body.step(0.5 * body.stableTimeStep(), Vec3::Zero(), {}, {});
    EXPECT_LT((body.linearMomentum() - before).norm(), 1e-10 * before.norm()) << softIntegratorName(integrator);
  }
}

TEST(SoftBody, DroppedBlockRestsOnTheGroundWithoutSinking) {
  SoftBodyDef def = block(ConstitutiveModel::Corotated);
  def.position = Vec3(0.0, 1.5, 0.0);
  def.damping = 50.0;
  SoftBody body(def);
  const std::vector<Plane> ground = {Plane{}};
  const std::vector<Material> groundMaterial = {Material{}};
  const double dt = 1.0 / 240.0;
  for (int step = 0; step < 2400; ++step) {
    body.step(dt, Vec3(0.0, -9.81, 0.0), ground, groundMaterial);
    for (const Vec3& x : body.positions()) ASSERT_GE(x.y(), -1e-12) << "step " << step;
  }
  double fastest = 0.0;
  for (const Vec3& v : body.velocities()) fastest = std::max(fastest, v.norm());
  EXPECT_LT(fastest, 0.001) << "at rest after 10 s";
  // Squashed under its own weight by centimetres (rho g h^2 / (2 E) = 4.9 cm for a free column).
  double top = 0.0;
  for (const Vec3& x : body.positions()) top = std::max(top, x.y());
  EXPECT_NEAR(top, 1.0, 0.05);
  EXPECT_LT(top, 1.0);
}

}  // namespace
}  // namespace rbsim
