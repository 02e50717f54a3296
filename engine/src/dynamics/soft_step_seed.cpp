// The soft step's sweep with seed 000's friction at every point (Settings::FrictionModel::Seed000,
// seed_friction.h): the normal rows of soft_step_solver.cpp's solve, with their bias and
// softness, then each point's static-then-kinetic tangential impulse with its K_T.
#include <algorithm>
#include <cmath>

#include "rbsim/dynamics/impulse.h"
#include "dynamics/seed_friction.h"
#include "rbsim/dynamics/soft_step_solver.h"

namespace rbsim {

void SoftStepSolver::solveSeed(std::size_t island, double inverseH, const Settings& settings, bool useBias,
                               bool lastRelax) {
  islands_.forContacts(island, [&](std::size_t index) {
    Constraint& c = constraints_[index];
    SolverState& A = states_[c.a];
    SolverState& B = states_[c.b];
    const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
    const Mat3& iA = sims_[c.a].inverseInertiaNow;
    const Mat3& iB = sims_[c.b].inverseInertiaNow;
    Vec3 vA = A.linearVelocity, wA = A.angularVelocity, vB = B.linearVelocity, wB = B.angularVelocity;
    const Vec3& n = c.normal;
    bool sticking = true;
    solveNormals(c, inverseH, settings, useBias, lastRelax, vA, wA, vB, wB);
    for (std::size_t k = 0; k < c.pointCount; ++k) {
      Point& p = points_[c.firstPoint + k];
      const PointReport& r = reports_[c.firstPoint + k];
      const Vec3 u = vB + wB.cross(p.anchorB) - vA - wA.cross(p.anchorA);  // u_rel, body 1 = B
      const Mat3 factor = impulseFactor(mA, iA, p.anchorA) + impulseFactor(mB, iB, p.anchorB);
      const Vec3 accumulated = p.tangentImpulse[0] * c.tangent1 + p.tangentImpulse[1] * c.tangent2;
      const SeedFriction next = seedFriction(factor, u, c.tangent1, c.tangent2, accumulated, p.normalImpulse,
                                             c.staticFriction, c.kineticFriction, r.sliding);
      sticking = sticking && next.sticking;
      const Vec3 delta = next.total - accumulated;
      p.tangentImpulse = {next.total.dot(c.tangent1), next.total.dot(c.tangent2)};
      vA -= mA * delta;
      wA -= iA * p.anchorA.cross(delta);
      vB += mB * delta;
      wB += iB * p.anchorB.cross(delta);
    }
    if (lastRelax) {
      // Each point's regime for the next step (seed_friction.h), and the patch's for the report.
      double slip = 0.0;
      for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
        const Point& p = points_[j];
        const Vec3 v = vB + wB.cross(p.anchorB) - vA - wA.cross(p.anchorA);
        const double pointSlip = (v - v.dot(n) * n).norm();
        reports_[j].sliding = pointSlip > kSeedSlidingSpeed;
        slip = std::max(slip, pointSlip);
      }
      c.slipping = !sticking && slip > kSeedSlidingSpeed;
    }
    storeVelocities(c.a, vA, wA);
    storeVelocities(c.b, vB, wB);
  });
}

}  // namespace rbsim
