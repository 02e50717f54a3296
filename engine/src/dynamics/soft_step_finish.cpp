// What the soft step does after its substeps (soft_step_solver.h): the restitution pass, the
// points reported to the World, the impulses kept for the next step's warm start, and the new
// state written back to the bodies.
#include <algorithm>
#include <cmath>

#include "dynamics/soft_step_solver.h"
#include "rbsim/dynamics/impulse.h"

namespace rbsim {

namespace {

// Gauss-Seidel sweeps of the restitution pass. One sweep (Box2D v3's) leaves a box landing flat
// on four points with uneven bounces, each point's impulse disturbing the ones already done; a
// few more converge them to one common rebound.
constexpr int kRestitutionSweeps = 16;
// Sweeps of the collision pass: each passes a hit at least one pair further down a chain, so a
// row of this many touching balls is the longest that hands it on within one step.
constexpr int kCollisionSweeps = 32;
// The collision pass reverses points closer than this: touching, as balls in a row are.
constexpr double kTouchingGap = 1e-6;  // [m]

}  // namespace

void SoftStepSolver::collide(const Settings& settings) {
  // Seed 000 "Collision": u_rel,N^new = -c_R u_rel,N, one point at a time, each with the
  // velocities the points before it left, and swept until nothing approaches (Guendelman,
  // Bridson, Fedkiw 2003, "Nonconvex rigid bodies with stacking", collision processing before
  // contact processing): a ball hitting a row of touching balls hands its momentum on pair by
  // pair, as Newton's cradle does, where one simultaneous solve would move the row together.
  // Only pairs touching at one point: a patch (a box landing flat) bounces in applyRestitution,
  // whose sweeps share the rebound among its points instead of tipping it at the first one.
  // With Settings::friction = seed000 the collision takes seed 000's whole impulse, friction
  // included (collisionImpulse, dynamics/impulse.h), as the seed writes it for one collision.
  const double dt = settings.timeStep;
  for (int sweep = 0; sweep < kCollisionSweeps; ++sweep) {
    bool collided = false;
    for (const Constraint& c : constraints_) {
      if (c.pointCount != 1 || c.restitution == 0.0) continue;
      Point& p = points_[c.firstPoint];
      SolverState& A = states_[c.a];
      SolverState& B = states_[c.b];
      const Vec3& n = c.normal;
      const double vn = normalVelocity(c, p, A, B);
      // Slower approaches are resting contact; a gap the approach does not close within the step
      // is left for a later step.
      if (-vn <= settings.restitutionThreshold || p.separation + vn * dt > settings.contactSlop) continue;
      // A point still short of the surface meets it within the substeps, and bounces in
      // applyRestitution with its speed at the touch: reversed here, above the ground, it lost the
      // energy of the gap (a ball dropped 1 cm left at 37 % of c_R u_c at 1/60 s, or not at all).
      if (p.separation > kTouchingGap) continue;
      PointReport& report = reports_[c.firstPoint];
      report.impactSpeed = 0.0;  // it has bounced: applyRestitution must not bounce it again
      collided = true;
      if (settings.friction == Settings::FrictionModel::Seed000) {
        // Seed 000 "Friction", literally: the whole impulse of the collision from the 3x3 K_T,
        // sticking if inside the mu_s cone, kinetic (N - mu_k T) j_n otherwise.
        const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
        const Mat3& iA = sims_[c.a].inverseInertiaNow;
        const Mat3& iB = sims_[c.b].inverseInertiaNow;
        const Vec3& rA = p.anchorA;
        const Vec3& rB = p.anchorB;
        const Vec3 u = B.linearVelocity + B.angularVelocity.cross(rB) - A.linearVelocity -
                       A.angularVelocity.cross(rA);  // u_rel, body 1 = B
        const CollisionImpulse hit = collisionImpulse<3>(impulseFactor(mA, iA, rA) + impulseFactor(mB, iB, rB), u, n,
                                                         Material{c.restitution, c.staticFriction, c.kineticFriction});
        const Vec3& j = hit.impulse;
        report.totalNormalImpulse += j.dot(n);
        report.totalFriction += j - j.dot(n) * n;
        report.sliding = !hit.sticking;  // the regime the substeps carry on with
        applyImpulse(c, p, j, A, B);
        continue;
      }
      const double impulse = -(1.0 + c.restitution) * vn * p.normalMass;  // j = N j_n only
      report.totalNormalImpulse += impulse;
      applyImpulse(c, p, impulse * n, A, B);
    }
    if (!collided) return;
  }
}

void SoftStepSolver::applyRestitution(const Settings& settings) {
  // Box2D v3's b2ApplyRestitution, with the speed at the touch instead of the speed at the step's
  // start: a ball dropped onto the ground bounces with the speed it reached, not with the speed
  // it had up to a step earlier, so e = 1 neither gains nor loses the energy of that last gap.
  for (int sweep = 0; sweep < kRestitutionSweeps; ++sweep) {
    for (const Constraint& c : constraints_) {
      if (c.restitution == 0.0) continue;
      SolverState& A = states_[c.a];
      SolverState& B = states_[c.b];
      const Vec3& n = c.normal;
      // A manifold whose surfaces never met, or met without pushing, did not collide (a
      // warm-started speculative contact must not bounce early).
      if (!c.touched) continue;
      for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
        Point& p = points_[j];
        // Slower approaches are resting contact. Every point the step ends touching bounces,
        // not only those that pushed: in a Gauss-Seidel sweep the first point of a box landing
        // flat stops it alone, and bouncing that point alone would set the box spinning.
        const PointReport& r = reports_[j];
        if (r.impactSpeed <= settings.restitutionThreshold || p.separation > settings.contactSlop) continue;
        const double vn = normalVelocity(c, p, A, B);
        // Seed 000: u_rel,N^new = c_R u_rel,N at the touch.
        const double impulse = -p.normalMass * (vn - c.restitution * r.impactSpeed);
        const double total = std::max(p.normalImpulse + impulse, 0.0);
        const double delta = total - p.normalImpulse;
        p.normalImpulse = total;
        reports_[j].totalNormalImpulse += delta;
        applyImpulse(c, p, delta * n, A, B);
      }
    }
  }
}

void SoftStepSolver::report() const {
  solved_.clear();
  for (const Constraint& c : constraints_) {
    const SolverState& A = states_[c.a];
    const SolverState& B = states_[c.b];
    for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
      const PointReport& r = reports_[j];
      SolvedContactPoint out;
      out.contact = c.contact;
      out.position = r.position;
      out.normal = c.normal;
      out.depth = r.depth;
      out.normalImpulse = r.totalNormalImpulse;
      out.frictionImpulse = r.totalFriction;
      out.approachVelocity = r.relativeVelocity;
      out.normalVelocity = normalVelocity(c, points_[j], A, B);
      out.sticking = c.sticking && !c.slipping;
      solved_.push_back(out);
    }
  }
  reported_ = true;
}

void SoftStepSolver::finish(std::vector<RigidBody>& bodies) {
  for (const Constraint& c : constraints_) {
    Cached cache;
    cache.key = c.key;
    cache.count = static_cast<int>(c.pointCount);
    for (std::size_t j = 0; j < c.pointCount; ++j) {
      const Point& p = points_[c.firstPoint + j];
      cache.localPoints[j] = frames_[c.firstPoint + j].localB;
      cache.normalImpulses[j] = p.normalImpulse;
      cache.sliding[j] = reports_[c.firstPoint + j].sliding;
      cache.frictionImpulses[j] = p.tangentImpulse[0] * c.tangent1 + p.tangentImpulse[1] * c.tangent2;
    }
    cache.sticking = !c.slipping;
    nextCache_.push_back(cache);
  }
  std::sort(nextCache_.begin(), nextCache_.end(), [](const Cached& a, const Cached& b) { return a.key < b.key; });
  cache_.swap(nextCache_);
  nextCache_.clear();
  indexCache();
  reported_ = false;

  for (std::size_t i = 1; i < states_.size(); ++i) {
    const SolverState& s = states_[i];
    RigidBody& body = bodies[sims_[i].body];
    rbsim::BodyState state = body.state();
    state.position += s.deltaPosition;
    state.orientation = s.orientation.normalized();
    state.linearMomentum = body.mass() * s.linearVelocity;
    const Mat3 R = state.orientation.toRotationMatrix();
    state.angularMomentum = R * (body.inertiaBody() * (R.transpose() * s.angularVelocity));
    body.setState(state);
    body.clearAccumulators();
    slotOfBody_[sims_[i].body] = 0;
  }
}

}  // namespace rbsim
