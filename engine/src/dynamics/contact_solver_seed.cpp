// PGS with seed 000's friction at every point (Settings::FrictionModel::Seed000,
// seed_friction.h): after a patch's normal rows, each point's static-then-kinetic tangential
// impulse with its K_T, in place of the patch's friction at its centroid.
#include "rbsim/dynamics/contact_solver.h"
#include "rbsim/dynamics/impulse.h"
#include "dynamics/seed_friction.h"

namespace rbsim {

void ContactSolver::applySeed(const Patch& patch, const NormalRow& row, const Vec3& impulse) {
  // Seed 002 2.2.1: dP = j, dL = r x j on body 1; the opposite on body 2 at the same point.
  const SolverBody& b1 = bodies_[patch.body1];
  const SolverBody& b2 = bodies_[patch.body2];
  Velocity& v1 = velocities_[patch.body1];
  Velocity& v2 = velocities_[patch.body2];
  v1.linear += b1.inverseMass * impulse;
  v1.angular += b1.inverseInertiaWorld * row.arm1.cross(impulse);
  v2.linear -= b2.inverseMass * impulse;
  v2.angular -= b2.inverseInertiaWorld * row.arm2.cross(impulse);
}

void ContactSolver::solveSeedFriction(const Patch& patch, NormalRow& row) {
  const SolverBody& b1 = bodies_[patch.body1];
  const SolverBody& b2 = bodies_[patch.body2];
  const Velocity& v1 = velocities_[patch.body1];
  const Velocity& v2 = velocities_[patch.body2];
  // u_rel = u_1 - u_2 at the point, K_T = K_1 + K_2 (seed 000 "Collision Response").
  const Vec3 u = v1.linear + v1.angular.cross(row.arm1) - v2.linear - v2.angular.cross(row.arm2);
  const Mat3 factor = impulseFactor(b1.inverseMass, b1.inverseInertiaWorld, row.arm1) +
                      impulseFactor(b2.inverseMass, b2.inverseInertiaWorld, row.arm2);
  const SeedFriction next =
      seedFriction(factor, u, patch.tangent1, patch.tangent2, row.friction, row.impulse,
                   patch.material.staticFriction, patch.material.kineticFriction, row.sliding);
  applySeed(patch, row, next.total - row.friction);
  row.friction = next.total;
  row.sticking = next.sticking;
}

void ContactSolver::markSliding() {
  for (const Patch& patch : patches_) {
    const Velocity& v1 = velocities_[patch.body1];
    const Velocity& v2 = velocities_[patch.body2];
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      NormalRow& row = rows_[r];
      const Vec3 u = v1.linear + v1.angular.cross(row.arm1) - v2.linear - v2.angular.cross(row.arm2);
      row.sliding = (u - u.dot(patch.normal) * patch.normal).norm() > kSeedSlidingSpeed;
    }
  }
}

}  // namespace rbsim
