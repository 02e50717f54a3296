#include "dynamics/pgs_solver.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "dynamics/contact_key.h"
#include "dynamics/friction_law.h"
#include "rbsim/dynamics/impulse.h"
#include "rbsim/integrate/integrator.h"

namespace rbsim {

int PgsSolver::solverBody(std::vector<RigidBody>& bodies, std::size_t body) {
  if (bodies[body].isStatic()) return 0;
  int& slot = slotOfBody_[body];
  if (slot != 0) return slot;
  const RigidBody& b = bodies[body];
  // A kinematic body: infinite mass (seed 000's K = 0), its prescribed velocity in the relative one.
  if (b.isKinematic()) {
    bodies_.push_back(SolverBody{0.0, Mat3::Zero(), body});
  } else {
    bodies_.push_back(SolverBody{1.0 / b.mass(), b.inverseInertiaWorld(), body});
  }
  velocities_.push_back(Velocity{b.velocity(), b.angularVelocity()});
  slot = static_cast<int>(bodies_.size() - 1);
  return slot;
}

void PgsSolver::bodiesRemoved(const std::vector<std::uint32_t>& removed,
                              const std::vector<std::uint64_t>& /*goneAsleep: its cache holds every warm start*/) {
  solved_.clear();
  dropRemoved(cache_, removed);
}

const PgsSolver::Cached* PgsSolver::cached(std::uint64_t key) const {
  const auto it = std::lower_bound(cache_.begin(), cache_.end(), key,
                                   [](const Cached& c, std::uint64_t k) { return c.key < k; });
  return it != cache_.end() && it->key == key ? &*it : nullptr;
}

double PgsSolver::normalVelocity(const Patch& patch, const NormalRow& row) const {
  // u_rel,N = N . (v1 + omega1 x r1 - v2 - omega2 x r2) (seed 000), with (omega x r) . n written
  // as omega . (r x n).
  const Velocity& v1 = velocities_[patch.body1];
  const Velocity& v2 = velocities_[patch.body2];
  return patch.normal.dot(v1.linear - v2.linear) + row.angular1.dot(v1.angular) - row.angular2.dot(v2.angular);
}

void PgsSolver::applyNormal(const Patch& patch, const NormalRow& row, double impulse,
                                std::vector<Velocity>& velocities) const {
  // Seed 002 2.2.1: dP = j, dL = r x j; body 2 receives the opposite at the same point.
  Velocity& v1 = velocities[patch.body1];
  Velocity& v2 = velocities[patch.body2];
  v1.linear += (bodies_[patch.body1].inverseMass * impulse) * patch.normal;
  v1.angular += impulse * row.angularStep1;
  v2.linear -= (bodies_[patch.body2].inverseMass * impulse) * patch.normal;
  v2.angular -= impulse * row.angularStep2;
}

void PgsSolver::applyFriction(const Patch& patch, const Vec3& impulse) {
  // The tangential impulse at the centroid and the angular impulse about n (seed 002 2.2.1).
  const Vec3 linear = impulse.x() * patch.tangent1 + impulse.y() * patch.tangent2;
  Velocity& v1 = velocities_[patch.body1];
  Velocity& v2 = velocities_[patch.body2];
  v1.linear += bodies_[patch.body1].inverseMass * linear;
  v1.angular += patch.angularStep1 * impulse;
  v2.linear -= bodies_[patch.body2].inverseMass * linear;
  v2.angular -= patch.angularStep2 * impulse;
}

void PgsSolver::buildPatch(std::vector<RigidBody>& bodies, const Contact& contact, std::size_t index, std::uint64_t key,
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

  // Where each point acts: the manifold's point, midway between the surfaces, except that a
  // round side touching a flat one at a single point takes it on its own surface: the bounce of
  // a ball still above the ground has lever arm R, not R + gap / 2, and a ball this solver meets
  // d deep (it integrates first) must leave rolling on R, not on R - d / 2 (it left 0.27 m/s
  // overspun). A face's patch (a rounded box lying flat) keeps the midpoints: moved, a stack of
  // three rounded boxes at 1/60 s crept 5 cm sideways in 3 s.
  const auto round = [&](std::size_t body, std::uint16_t child) {
    const RigidBody& r = bodies[body];
    return (r.isCompound() ? r.children()[child].shape : r.shape()).isRound();
  };
  const bool round1 = round(contact.b, contact.childB), round2 = !plane && round(contact.a, contact.childA);
  const double side = round1 == round2 || m.count != 1 ? 0.0 : round1 ? 0.5 : -0.5;  // n points towards body 1
  std::array<Vec3, kMaxManifoldPoints> points{};
  for (int i = 0; i < m.count; ++i) points[i] = m.points[i].position - side * m.points[i].depth * m.normal;
  Vec3 centroid = Vec3::Zero();
  for (int i = 0; i < m.count; ++i) centroid += points[i] / m.count;
  for (int i = 0; i < m.count; ++i) patch.twistRadius += (points[i] - centroid).norm() / m.count;
  const Vec3 c1 = centroid - b1.position();
  const Vec3 c2 = plane ? Vec3::Zero() : Vec3(centroid - x2);
  patch.angular1 << c1.cross(patch.tangent1), c1.cross(patch.tangent2), n;
  patch.angular2 << c2.cross(patch.tangent1), c2.cross(patch.tangent2), n;
  patch.angularStep1 = s1.inverseInertiaWorld * patch.angular1;
  patch.angularStep2 = s2.inverseInertiaWorld * patch.angular2;
  patch.inverseFriction =
      (frictionImpulseFactor(s1.inverseMass, s1.inverseInertiaWorld, c1, patch.tangent1, patch.tangent2, n) +
       frictionImpulseFactor(s2.inverseMass, s2.inverseInertiaWorld, c2, patch.tangent1, patch.tangent2, n))
          .inverse();

  const Cached* old = settings.warmStarting ? cached(key) : nullptr;
  bool collision = false, collisionSlides = false;
  for (int i = 0; i < m.count; ++i) {
    NormalRow row;
    const Vec3& p = points[i];
    const Vec3 r1 = p - b1.position();
    const Vec3 r2 = plane ? Vec3::Zero() : Vec3(p - x2);
    row.localPoint1 = b1.rotation().transpose() * r1;
    row.arm1 = r1;
    row.arm2 = r2;
    row.angular1 = r1.cross(n);
    row.angular2 = r2.cross(n);
    row.angularStep1 = s1.inverseInertiaWorld * row.angular1;
    row.angularStep2 = s2.inverseInertiaWorld * row.angular2;
    // N^T K_T N with K = (1/m) 1 + r*^T I^-1 r* (seed 000): 1/m1 + 1/m2 + (r1 x n) I1^-1 (r1 x n) + ...
    row.normalMass = 1.0 / (s1.inverseMass + s2.inverseMass + row.angular1.dot(row.angularStep1) +
                            row.angular2.dot(row.angularStep2));
    const double approach = normalVelocity(patch, row);
    const double gap = -m.points[i].depth;
    // Bounce (seed 000: u_rel,N^new = -c_R u_rel,N) when the approach is fast enough to be a
    // collision rather than resting contact, and the gap closes within the next step.
    // Otherwise a speculative contact may close its gap in one step, a touching one not at all.
    // The bounce leaves from here, up to |u| dt short of the surface, after a whole step of the
    // applied acceleration a_N (gravity): it gets the speed that carries it back as far as c_R
    // times the speed at the touch would, u_c^2 = u_0^2 - 2 a_N s_0 from the step's start. Seed
    // 000's -c_R u_rel,N from here gave a ball dropped 1 cm at 1/60 s 19-80 % more than c_R u_c.
    const double normalAcceleration = n.dot((s1.inverseMass > 0.0 ? settings.gravity : Vec3::Zero()) -
                                            (s2.inverseMass > 0.0 ? settings.gravity : Vec3::Zero()));
    // (The step's drift taken as the exact one under constant acceleration, dt (u_0 + u) / 2.)
    const double startApproach = approach - normalAcceleration * dt;
    const double startGap = std::max(gap - 0.5 * (startApproach + approach) * dt, 0.0);
    const double touch = startApproach * startApproach - 2.0 * normalAcceleration * startGap;
    const double leave = material.restitution * material.restitution * touch + 2.0 * normalAcceleration * std::max(gap, 0.0);
    // Below leave = 0 the bounce would not reach back here at all: the body keeps its approach
    // through the surface, and bounces in the next step with the speed it hit it at (the split
    // impulse takes it out of the ground without energy). Reversed here with seed 000's
    // -c_R u_rel,N, it gained the gap's energy: a c_R = 0.3 ball dropped 1 cm left at 2.4 c_R u_c
    // at 1/60 s, 1.6 at 1/240 s; held to the gap, it reached the surface slower and stayed there.
    const bool collides =
        material.restitution > 0.0 && approach < -settings.restitutionThreshold && -approach * dt >= gap;
    const bool bounces = collides && leave >= 0.0;
    row.targetNormalVelocity = bounces ? std::sqrt(leave) : collides ? approach : -std::max(gap, 0.0) / dt;
    row.correctionVelocity = std::max(0.0, settings.positionCorrection * (-gap - settings.contactSlop) / dt);
    if (old != nullptr) {
      for (int j = 0; j < old->count; ++j) {
        if ((old->localPoints[j] - row.localPoint1).norm() <= settings.warmStartDistance) {
          row.impulse = old->normalImpulses[j];
          row.friction = old->pointFriction[j] - old->pointFriction[j].dot(n) * n;
          row.sliding = old->sliding[j];
          break;
        }
      }
    }
    // Seed 000's regime at a collision (approaching faster than the restitution threshold), for
    // either model: sliding when its sticking impulse leaves the mu_s cone (collisionImpulse).
    // A resting point keeps the regime its last step ended in; a new one first assumes sticking.
    if (approach < -settings.restitutionThreshold) {
      const Velocity& v1 = velocities_[patch.body1];
      const Velocity& v2 = velocities_[patch.body2];
      const Vec3 u = v1.linear + v1.angular.cross(r1) - v2.linear - v2.angular.cross(r2);
      const Mat3 factor = impulseFactor(s1.inverseMass, s1.inverseInertiaWorld, r1) +
                          impulseFactor(s2.inverseMass, s2.inverseInertiaWorld, r2);
      const CollisionImpulse hit = collisionImpulse<3>(factor, u, n, material);
      row.sliding = hit.colliding && !hit.sticking;
      collision = collision || hit.colliding;
      collisionSlides = collisionSlides || row.sliding;
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
  patch.sticking = old == nullptr || old->sticking;
  if (collision) patch.sticking = !collisionSlides;  // the cone's regime is the patch's
  if (old != nullptr) {
    // Last step's friction, in this step's tangent plane and inside this step's cone.
    const double limit = material.staticFriction * normalImpulse(patch);
    Vec3 linear = old->linearFriction - old->linearFriction.dot(n) * n;
    if (linear.norm() > limit) linear *= limit / linear.norm();
    const double twistLimit = limit * patch.twistRadius;
    patch.friction = Vec3(linear.dot(patch.tangent1), linear.dot(patch.tangent2),
                          std::clamp(old->twistFriction, -twistLimit, twistLimit));
  }
  patches_.push_back(patch);
  patchContact_.push_back(index);
}

double PgsSolver::normalImpulse(const Patch& patch) const {
  double total = 0.0;
  for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) total += rows_[r].impulse;
  return total;
}

void PgsSolver::solveNormal(Patch& patch, NormalRow& row) {
  const double u = normalVelocity(patch, row);
  // Seed 000's j_n for the target velocity, accumulated and kept repulsive (seed 001: f_i >= 0).
  const double total = std::max(0.0, row.impulse + row.normalMass * (row.targetNormalVelocity - u));
  applyNormal(patch, row, total - row.impulse, velocities_);
  row.impulse = total;
}

void PgsSolver::solveFriction(Patch& patch) {
  const double normalTotal = normalImpulse(patch);
  const Velocity& v1 = velocities_[patch.body1];
  const Velocity& v2 = velocities_[patch.body2];
  // Slip along t1, t2 at the centroid and twist about n: S^T (v1 - v2, ...) through the Jacobians.
  const Vec3 dv = v1.linear - v2.linear;
  const Vec3 w = Vec3(dv.dot(patch.tangent1), dv.dot(patch.tangent2), 0.0) +
                 patch.angular1.transpose() * v1.angular - patch.angular2.transpose() * v2.angular;
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
  applyFriction(patch, total - patch.friction);
  patch.friction = total;
}

void PgsSolver::solvePosition(const Patch& patch, NormalRow& row) {
  const Velocity& p1 = pseudoVelocities_[patch.body1];
  const Velocity& p2 = pseudoVelocities_[patch.body2];
  const double u = patch.normal.dot(p1.linear - p2.linear) + row.angular1.dot(p1.angular) - row.angular2.dot(p2.angular);
  const double total = std::max(0.0, row.pseudoImpulse + row.normalMass * (row.correctionVelocity - u));
  applyNormal(patch, row, total - row.pseudoImpulse, pseudoVelocities_);
  row.pseudoImpulse = total;
}

void PgsSolver::writeBack(std::vector<RigidBody>& bodies, double dt) {
  // Delta P and Delta L from the accumulated impulses (the warm start's included), each applied
  // +j to body 1 and -j to body 2 at the same point, so momentum is exchanged exactly.
  std::vector<Vec3>& linear = linearImpulse_;
  std::vector<Vec3>& angular = angularImpulse_;
  linear.assign(bodies_.size(), Vec3::Zero());
  angular.assign(bodies_.size(), Vec3::Zero());
  for (const Patch& patch : patches_) {
    Vec3 j = patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2;
    Vec3 l1 = patch.angular1 * patch.friction, l2 = patch.angular2 * patch.friction;
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      j += rows_[r].impulse * patch.normal + rows_[r].friction;
      l1 += rows_[r].impulse * rows_[r].angular1 + rows_[r].arm1.cross(rows_[r].friction);
      l2 += rows_[r].impulse * rows_[r].angular2 + rows_[r].arm2.cross(rows_[r].friction);
    }
    linear[patch.body1] += j;
    angular[patch.body1] += l1;
    linear[patch.body2] -= j;
    angular[patch.body2] -= l2;
  }
  for (std::size_t i = 1; i < bodies_.size(); ++i) {
    RigidBody& body = bodies[bodies_[i].body];
    slotOfBody_[bodies_[i].body] = 0;
    if (body.isKinematic()) continue;  // moves as prescribed: no impulse or correction changes it
    BodyState state = body.state();
    state.linearMomentum += linear[i];
    state.angularMomentum += angular[i];
    // The split impulse's pseudo-velocities move the body out of penetration over one step and
    // are then forgotten, so the correction never becomes kinetic energy.
    state.position += dt * pseudoVelocities_[i].linear;
    state.orientation = expMapStep(state.orientation, pseudoVelocities_[i].angular, dt);
    body.setState(state);
  }
}

void PgsSolver::remember(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys) {
  nextCache_.clear();
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const Patch& patch = patches_[p];
    Cached c;
    c.key = pairKey(contacts[patchContact_[p]], bodyKeys);
    c.count = static_cast<int>(patch.rowCount);
    for (int i = 0; i < c.count; ++i) {
      c.localPoints[i] = rows_[patch.firstRow + i].localPoint1;
      c.normalImpulses[i] = rows_[patch.firstRow + i].impulse;
      c.pointFriction[i] = rows_[patch.firstRow + i].friction;
      c.sliding[i] = rows_[patch.firstRow + i].sliding;
    }
    c.linearFriction = patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2;
    c.twistFriction = patch.friction.z();
    c.sticking = patch.insideCone;
    nextCache_.push_back(c);
  }
  std::sort(nextCache_.begin(), nextCache_.end(), [](const Cached& a, const Cached& b) { return a.key < b.key; });
  cache_.swap(nextCache_);
}

void PgsSolver::solve(const SolverInput& input) {
  std::vector<RigidBody>& bodies = input.bodies;
  const std::vector<Contact>& contacts = input.contacts;
  const Settings& settings = input.settings;
  bodies_.assign(1, SolverBody{});
  velocities_.assign(1, Velocity{});
  slotOfBody_.resize(bodies.size(), 0);
  patches_.clear();
  patchContact_.clear();
  rows_.clear();
  solved_.clear();
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const Contact& contact = contacts[c];
    const bool plane = contact.kind == Contact::Kind::PlaneBody;
    const Material material = contactMaterial(input, contact);
    // A sleeping pair receives nothing (World wakes the sleeping side of a pair with an awake one).
    const bool awake = bodies[contact.b].awake() || (!plane && bodies[contact.a].awake());
    if (contact.manifold.count > 0 && awake) buildPatch(bodies, contact, c, pairKey(contact, input.bodyIds.slotOfItem()), material, settings);
  }

  pseudoVelocities_.assign(bodies_.size(), Velocity{});
  for (const Patch& patch : patches_) {  // warm start
    applyFriction(patch, patch.friction);
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      applyNormal(patch, rows_[r], rows_[r].impulse, velocities_);
      applyPointFriction(patch, rows_[r], rows_[r].friction);  // zero unless seed000
    }
  }
  const bool seed = settings.friction == Settings::FrictionModel::Seed000;
  // Friction first, non-penetration last in each sweep: the condition that matters most is the
  // one the sweep leaves exactly satisfied (Box2D's order).
  // Sweeps alternate direction (symmetric Gauss-Seidel): a one-way sweep favours the rows it
  // visits last, which tilts symmetric stacks and spins boxes landing flat.
  for (int k = 0; k < settings.velocityIterations; ++k) {
    const bool forward = k % 2 == 0;
    for (std::size_t i = 0; i < patches_.size(); ++i) {
      Patch& patch = patches_[forward ? i : patches_.size() - 1 - i];
      if (!seed) solveFriction(patch);
      for (std::size_t j = 0; j < patch.rowCount; ++j) {
        solveNormal(patch, rows_[patch.firstRow + (forward ? j : patch.rowCount - 1 - j)]);
      }
      // Seed 000's friction per point, after the normal rows (Box2D v3's order, as soft step).
      for (std::size_t j = 0; seed && j < patch.rowCount; ++j) {
        solvePointFriction(patch, rows_[patch.firstRow + (forward ? j : patch.rowCount - 1 - j)], settings.friction);
      }
    }
  }
  if (seed) markSliding();
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
      out.normalVelocity = normalVelocity(patch, rows_[r]);
      out.sticking = patch.sticking && patch.insideCone;
      if (seed) {
        out.frictionImpulse = rows_[r].friction;
        out.sticking = rows_[r].sticking;
      }
    }
  }
  writeBack(bodies, settings.timeStep);
  remember(contacts, input.bodyIds.slotOfItem());
}

void PgsSolver::applyPointFriction(const Patch& patch, const NormalRow& row, const Vec3& impulse) {
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

void PgsSolver::solvePointFriction(const Patch& patch, NormalRow& row, Settings::FrictionModel model) {
  const SolverBody& b1 = bodies_[patch.body1];
  const SolverBody& b2 = bodies_[patch.body2];
  const Velocity& v1 = velocities_[patch.body1];
  const Velocity& v2 = velocities_[patch.body2];
  // u_rel = u_1 - u_2 at the point, K_T = K_1 + K_2 (seed 000 "Collision Response").
  const Vec3 u = v1.linear + v1.angular.cross(row.arm1) - v2.linear - v2.angular.cross(row.arm2);
  const Mat3 factor = impulseFactor(b1.inverseMass, b1.inverseInertiaWorld, row.arm1) +
                      impulseFactor(b2.inverseMass, b2.inverseInertiaWorld, row.arm2);
  FrictionPoint point;
  point.accumulated = {patch.tangent1.dot(row.friction), patch.tangent2.dot(row.friction)};
  point.slip = {patch.tangent1.dot(u), patch.tangent2.dot(u)};
  point.tangentMass = {1.0 / patch.tangent1.dot(factor * patch.tangent1), 1.0 / patch.tangent2.dot(factor * patch.tangent2)};
  point.coupling = patch.tangent1.dot(factor * patch.tangent2);
  point.normalImpulse = row.impulse;
  point.staticFriction = patch.material.staticFriction;
  point.kineticFriction = patch.material.kineticFriction;
  point.sliding = row.sliding;
  const FrictionImpulse next = frictionImpulse(model, point);
  const Vec3 total = next.total[0] * patch.tangent1 + next.total[1] * patch.tangent2;
  applyPointFriction(patch, row, total - row.friction);
  row.friction = total;
  row.sticking = next.sticking;
}

void PgsSolver::markSliding() {
  for (const Patch& patch : patches_) {
    const Velocity& v1 = velocities_[patch.body1];
    const Velocity& v2 = velocities_[patch.body2];
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      NormalRow& row = rows_[r];
      const Vec3 u = v1.linear + v1.angular.cross(row.arm1) - v2.linear - v2.angular.cross(row.arm2);
      row.sliding = (u - u.dot(patch.normal) * patch.normal).norm() > kSlidingSpeed;
    }
  }
}

}  // namespace rbsim
