#include "dynamics/contact_solver.h"

#include <algorithm>
#include <cmath>

#include "dynamics/impulse.h"
#include "integrate/integrator.h"

namespace rbsim {

namespace {

std::uint64_t pairKey(const Contact& c) {
  const std::uint64_t kind = c.kind == Contact::Kind::PlaneBody ? 1u : 0u;
  return (kind << 63) | (static_cast<std::uint64_t>(c.a) << 32) | static_cast<std::uint64_t>(c.b);
}

// Two unit tangents completing the normal to a right-handed basis.
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  // Some component of a unit vector is at least 1/sqrt(3); crossing with x while |n.x| is below
  // that keeps the cross product well away from zero.
  const double oneOverSqrt3 = 1.0 / std::sqrt(3.0);
  const Vec3 seed = std::abs(n.x()) < oneOverSqrt3 ? Vec3::UnitX() : Vec3::UnitY();
  t1 = n.cross(seed).normalized();
  t2 = n.cross(t1);
}

// S^T K S for the friction coordinates (t1 and t2 at the point, twist about n): seed 002's 6x6 K
// with the rows and columns of the tangential impulse and the angular impulse about n.
Mat3 frictionFactor(const Mat6& k, const Vec3& t1, const Vec3& t2, const Vec3& n) {
  Eigen::Matrix<double, 6, 3> s = Eigen::Matrix<double, 6, 3>::Zero();
  s.block<3, 1>(0, 0) = t1;
  s.block<3, 1>(0, 1) = t2;
  s.block<3, 1>(3, 2) = n;
  return s.transpose() * k * s;
}

}  // namespace

int ContactSolver::solverBody(std::vector<RigidBody>& bodies, std::size_t body) {
  if (bodies[body].isStatic()) return 0;
  int& slot = slotOfBody_[body];
  if (slot != 0) return slot;
  const RigidBody& b = bodies[body];
  SolverBody s;
  s.velocity = b.velocity();
  s.angularVelocity = b.angularVelocity();
  s.inverseMass = 1.0 / b.mass();
  s.inverseInertiaWorld = b.inverseInertiaWorld();
  s.body = body;
  bodies_.push_back(s);
  slot = static_cast<int>(bodies_.size() - 1);
  return slot;
}

Vec3 ContactSolver::pointVelocity(int body, const Vec3& r) const {
  const SolverBody& s = bodies_[body];
  return s.velocity + s.angularVelocity.cross(r);  // u = v + omega x r (seed 000)
}

void ContactSolver::apply(int body1, int body2, const Vec3& r1, const Vec3& r2, const Vec3& linear,
                          const Vec3& angular) {
  // Seed 002 2.2.1: dP = j, dL = r x j + j_tau; body 2 receives the opposite at the same point.
  SolverBody& s1 = bodies_[body1];
  SolverBody& s2 = bodies_[body2];
  const Vec3 dL1 = r1.cross(linear) + angular;
  const Vec3 dL2 = r2.cross(linear) + angular;
  s1.velocity += s1.inverseMass * linear;
  s1.angularVelocity += s1.inverseInertiaWorld * dL1;
  s1.linearImpulse += linear;
  s1.angularImpulse += dL1;
  s2.velocity -= s2.inverseMass * linear;
  s2.angularVelocity -= s2.inverseInertiaWorld * dL2;
  s2.linearImpulse -= linear;
  s2.angularImpulse -= dL2;
}

void ContactSolver::buildPatch(std::vector<RigidBody>& bodies, const Contact& contact, std::size_t index,
                               const Material& material, const Settings& settings) {
  const double dt = settings.timeStep;
  const bool plane = contact.kind == Contact::Kind::PlaneBody;
  const ContactManifold& m = contact.manifold;
  Patch patch;
  patch.body1 = solverBody(bodies, contact.b);
  patch.body2 = plane ? 0 : solverBody(bodies, contact.a);
  patch.normal = m.normal;
  tangentBasis(patch.normal, patch.tangent1, patch.tangent2);
  patch.material = material;
  patch.firstRow = rows_.size();
  patch.rowCount = static_cast<std::size_t>(m.count);
  const RigidBody& b1 = bodies[contact.b];
  const Vec3 x2 = plane ? Vec3::Zero() : bodies[contact.a].position();
  const SolverBody& s1 = bodies_[patch.body1];
  const SolverBody& s2 = bodies_[patch.body2];
  const Vec3& n = patch.normal;

  Vec3 centroid = Vec3::Zero();
  for (int i = 0; i < m.count; ++i) centroid += m.points[i].position / m.count;
  for (int i = 0; i < m.count; ++i) patch.twistRadius += (m.points[i].position - centroid).norm() / m.count;
  patch.r1 = centroid - b1.position();
  patch.r2 = plane ? Vec3::Zero() : Vec3(centroid - x2);
  const Mat6 k = coupledImpulseFactor(s1.inverseMass, s1.inverseInertiaWorld, patch.r1) +
                 coupledImpulseFactor(s2.inverseMass, s2.inverseInertiaWorld, patch.r2);
  patch.inverseFriction = frictionFactor(k, patch.tangent1, patch.tangent2, n).inverse();

  const auto cached = settings.warmStarting ? cache_.find(pairKey(contact)) : cache_.end();
  for (int i = 0; i < m.count; ++i) {
    NormalRow row;
    const Vec3& p = m.points[i].position;
    row.r1 = p - b1.position();
    row.r2 = plane ? Vec3::Zero() : Vec3(p - x2);
    row.localPoint1 = b1.rotation().transpose() * row.r1;
    const Mat3 factor = impulseFactor(s1.inverseMass, s1.inverseInertiaWorld, row.r1) +
                        impulseFactor(s2.inverseMass, s2.inverseInertiaWorld, row.r2);
    row.normalMass = 1.0 / n.dot(factor * n);
    const double approach = (pointVelocity(patch.body1, row.r1) - pointVelocity(patch.body2, row.r2)).dot(n);
    const double gap = -m.points[i].depth;
    // Bounce (seed 000: u_rel,N^new = -c_R u_rel,N) when the approach is fast enough to be a
    // collision rather than resting contact, and the gap closes within the next step.
    // Otherwise a speculative contact may close its gap in one step, a touching one not at all.
    const bool bounces = approach < -settings.restitutionThreshold && -approach * dt >= gap;
    row.targetNormalVelocity = bounces ? -material.restitution * approach : -std::max(gap, 0.0) / dt;
    row.correctionVelocity = std::max(0.0, settings.positionCorrection * (-gap - settings.contactSlop) / dt);
    if (cached != cache_.end()) {
      const Cached& old = cached->second;
      for (std::size_t j = 0; j < old.localPoints.size(); ++j) {
        if ((old.localPoints[j] - row.localPoint1).norm() <= settings.warmStartDistance) {
          row.impulse = old.normalImpulses[j];
          break;
        }
      }
    }
    SolvedContactPoint out;
    out.contact = index;
    out.position = p;
    out.normal = n;
    out.depth = m.points[i].depth;
    out.approachVelocity = approach;
    rows_.push_back(row);
    solved_.push_back(out);
  }
  // A new patch first assumes sticking (seed 000); a known one keeps last step's regime, as its
  // final sweep left it: sliding when the sticking impulse was outside the cone, sticking again
  // when the kinetic one would stop the slip.
  patch.sticking = cached == cache_.end() || cached->second.sticking;
  if (cached != cache_.end()) {
    // Last step's friction, in this step's tangent plane and inside this step's cone.
    const double limit = material.staticFriction * normalImpulse(patch);
    Vec3 linear = cached->second.linearFriction - cached->second.linearFriction.dot(n) * n;
    if (linear.norm() > limit) linear *= limit / linear.norm();
    const double twistLimit = limit * patch.twistRadius;
    patch.friction = Vec3(linear.dot(patch.tangent1), linear.dot(patch.tangent2),
                          std::clamp(cached->second.twistFriction, -twistLimit, twistLimit));
  }
  patches_.push_back(patch);
  patchContact_.push_back(index);
}

double ContactSolver::normalImpulse(const Patch& patch) const {
  double total = 0.0;
  for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) total += rows_[r].impulse;
  return total;
}

void ContactSolver::solveNormal(Patch& patch, NormalRow& row) {
  const Vec3& n = patch.normal;
  const double u = (pointVelocity(patch.body1, row.r1) - pointVelocity(patch.body2, row.r2)).dot(n);
  // Seed 000's j_n for the target velocity, accumulated and kept repulsive (seed 001: f_i >= 0).
  const double total = std::max(0.0, row.impulse + row.normalMass * (row.targetNormalVelocity - u));
  apply(patch.body1, patch.body2, row.r1, row.r2, (total - row.impulse) * n, Vec3::Zero());
  row.impulse = total;
}

void ContactSolver::solveFriction(Patch& patch) {
  const double normalTotal = normalImpulse(patch);
  const Vec3& n = patch.normal;
  const Vec3 u = pointVelocity(patch.body1, patch.r1) - pointVelocity(patch.body2, patch.r2);
  const Vec3 w(u.dot(patch.tangent1), u.dot(patch.tangent2),
               (bodies_[patch.body1].angularVelocity - bodies_[patch.body2].angularVelocity).dot(n));
  // Seed 000: assume sticking (the impulse that stops slip and twist), then keep it inside the
  // cone, of mu_s while the patch sticks and of mu_k while it slides. Scaling onto the cone is
  // continuous, so the sweeps converge; switching the coefficient inside a step is not, and
  // cycles (the regime changes between steps: remember()).
  const Vec3 candidate = patch.friction - patch.inverseFriction * w;
  const double mu = patch.sticking ? patch.material.staticFriction : patch.material.kineticFriction;
  const double limit = mu * normalTotal;
  const double slipImpulse = candidate.head<2>().norm();
  patch.insideCone = slipImpulse <= limit && std::abs(candidate.z()) <= limit * patch.twistRadius;
  Vec3 total = candidate;
  if (slipImpulse > limit) total.head<2>() *= limit / slipImpulse;
  total.z() = std::clamp(candidate.z(), -limit * patch.twistRadius, limit * patch.twistRadius);
  const Vec3 delta = total - patch.friction;
  apply(patch.body1, patch.body2, patch.r1, patch.r2, delta.x() * patch.tangent1 + delta.y() * patch.tangent2,
        delta.z() * n);
  patch.friction = total;
}

void ContactSolver::solvePosition(const Patch& patch, NormalRow& row) {
  SolverBody& s1 = bodies_[patch.body1];
  SolverBody& s2 = bodies_[patch.body2];
  const Vec3& n = patch.normal;
  const double u = (s1.pseudoVelocity + s1.pseudoAngularVelocity.cross(row.r1) - s2.pseudoVelocity -
                    s2.pseudoAngularVelocity.cross(row.r2)).dot(n);
  const double total = std::max(0.0, row.pseudoImpulse + row.normalMass * (row.correctionVelocity - u));
  const Vec3 delta = (total - row.pseudoImpulse) * n;
  row.pseudoImpulse = total;
  s1.pseudoVelocity += s1.inverseMass * delta;
  s1.pseudoAngularVelocity += s1.inverseInertiaWorld * row.r1.cross(delta);
  s2.pseudoVelocity -= s2.inverseMass * delta;
  s2.pseudoAngularVelocity -= s2.inverseInertiaWorld * row.r2.cross(delta);
}

void ContactSolver::writeBack(std::vector<RigidBody>& bodies, double dt) {
  for (std::size_t i = 1; i < bodies_.size(); ++i) {
    const SolverBody& s = bodies_[i];
    RigidBody& body = bodies[s.body];
    BodyState state = body.state();
    state.linearMomentum += s.linearImpulse;
    state.angularMomentum += s.angularImpulse;
    // The split impulse's pseudo-velocities move the body out of penetration over one step and
    // are then forgotten, so the correction never becomes kinetic energy.
    state.position += dt * s.pseudoVelocity;
    state.orientation = expMapStep(state.orientation, s.pseudoAngularVelocity, dt);
    body.setState(state);
    slotOfBody_[s.body] = 0;
  }
}

void ContactSolver::remember(const std::vector<Contact>& contacts) {
  cache_.clear();
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const Patch& patch = patches_[p];
    Cached& c = cache_[pairKey(contacts[patchContact_[p]])];
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      c.localPoints.push_back(rows_[r].localPoint1);
      c.normalImpulses.push_back(rows_[r].impulse);
    }
    c.linearFriction = patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2;
    c.twistFriction = patch.friction.z();
    c.sticking = patch.insideCone;
  }
}

void ContactSolver::solve(std::vector<RigidBody>& bodies, const std::vector<Contact>& contacts,
                          const std::vector<Material>& bodyMaterials, const std::vector<Material>& planeMaterials,
                          const Settings& settings) {
  bodies_.assign(1, SolverBody{});
  slotOfBody_.resize(bodies.size(), 0);
  patches_.clear();
  patchContact_.clear();
  rows_.clear();
  solved_.clear();
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const Contact& contact = contacts[c];
    const bool plane = contact.kind == Contact::Kind::PlaneBody;
    const Material material =
        combine(bodyMaterials[contact.b], plane ? planeMaterials[contact.a] : bodyMaterials[contact.a]);
    // A sleeping pair receives nothing (World wakes the sleeping side of a pair with an awake one).
    const bool awake = bodies[contact.b].awake() || (!plane && bodies[contact.a].awake());
    if (contact.manifold.count > 0 && awake) buildPatch(bodies, contact, c, material, settings);
  }

  for (const Patch& patch : patches_) {  // warm start
    const Vec3& f = patch.friction;
    apply(patch.body1, patch.body2, patch.r1, patch.r2, f.x() * patch.tangent1 + f.y() * patch.tangent2,
          f.z() * patch.normal);
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      apply(patch.body1, patch.body2, rows_[r].r1, rows_[r].r2, rows_[r].impulse * patch.normal, Vec3::Zero());
    }
  }
  // Friction first, non-penetration last in each sweep: the condition that matters most is the
  // one the sweep leaves exactly satisfied (Box2D's order).
  // Sweeps alternate direction (symmetric Gauss-Seidel): a one-way sweep favours the rows it
  // visits last, which tilts symmetric stacks and spins boxes landing flat.
  for (int k = 0; k < settings.velocityIterations; ++k) {
    const bool forward = k % 2 == 0;
    for (std::size_t i = 0; i < patches_.size(); ++i) {
      Patch& patch = patches_[forward ? i : patches_.size() - 1 - i];
      solveFriction(patch);
      for (std::size_t j = 0; j < patch.rowCount; ++j) {
        solveNormal(patch, rows_[patch.firstRow + (forward ? j : patch.rowCount - 1 - j)]);
      }
    }
  }
  for (int k = 0; k < settings.positionIterations; ++k) {
    for (const Patch& patch : patches_) {
      for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) solvePosition(patch, rows_[r]);
    }
  }
  for (const Patch& patch : patches_) {
    const double normalTotal = normalImpulse(patch);
    const Vec3 friction = patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2;
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      SolvedContactPoint& out = solved_[r];
      out.normalImpulse = rows_[r].impulse;
      out.frictionImpulse = normalTotal > 0.0 ? Vec3(friction * (rows_[r].impulse / normalTotal)) : Vec3::Zero();
      out.normalVelocity = (pointVelocity(patch.body1, rows_[r].r1) - pointVelocity(patch.body2, rows_[r].r2)).dot(patch.normal);
      out.sticking = patch.sticking && patch.insideCone;
    }
  }
  writeBack(bodies, settings.timeStep);
  remember(contacts);
}

}  // namespace rbsim
