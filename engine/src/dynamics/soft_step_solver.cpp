#include "dynamics/soft_step_solver.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "dynamics/contact_key.h"
#include "dynamics/friction_law.h"
#include "rbsim/dynamics/impulse.h"
#include "rbsim/integrate/integrator.h"

namespace rbsim {

namespace {

// The stiffness of the contact spring is capped at this fraction of the substep rate: an implicit
// spring much stiffer than the substep can resolve only adds error. Box2D v3's solver.c caps
// contactHertz at a quarter of the substep rate, Box3D's physics_world.c at an eighth. Measured
// here (issue 54, a 10-row pyramid of Box3D's cubes, 1000 steps at 1/60 s): at a quarter, 60 Hz
// on 4 substeps or 30 Hz on 2, the pyramid gains energy step after step (6.5 J after 1000 steps
// on 2, rocking out of its plane); at 0.22 and below it comes to rest (2e-11 J at 52 Hz on 4).
// The default, 120 Hz on 10 substeps, is 0.2 and keeps its stiffness.
constexpr double kMaxHertzPerSubstepRate = 0.2;  // [1]

}  // namespace

int SoftStepSolver::slot(const std::vector<RigidBody>& bodies, std::size_t body, const Settings& settings,
                         bool addGravity) {
  const RigidBody& b = bodies[body];
  if (b.isStatic()) return 0;
  int& s = slotOfBody_[body];
  if (s != 0) return s;
  BodySim sim;
  sim.body = body;
  sim.position0 = b.position();
  sim.kinematic = b.isKinematic();
  if (!sim.kinematic) {  // a kinematic body keeps infinite mass and its prescribed velocities
    sim.inverseMass = 1.0 / b.mass();
    sim.inverseInertiaNow = b.inverseInertiaWorld();
    sim.acceleration = sim.inverseMass * b.force() + (addGravity ? settings.gravity : Vec3::Zero());
    sim.torque = b.torque() + b.rotation() * b.bodyTorque();  // the substeps hold both over the step
  }
  sims_.push_back(sim);
  inertias_.push_back({b.inertiaBody(), b.inverseInertiaBody()});
  poses_.push_back({b.rotation(), b.position()});
  states_.push_back(SolverState{b.velocity(), b.angularVelocity(), Vec3::Zero(), b.orientation()});
  s = static_cast<int>(sims_.size() - 1);
  advanced_[body] = 1;
  advancedList_.push_back(body);
  return s;
}

void SoftStepSolver::bodiesRemoved(const std::vector<std::uint32_t>& removed,
                                   const std::vector<std::uint64_t>& goneAsleep) {
  clearAdvanced();
  solved_.clear();
  hits_.clear();
  reported_ = true;
  // The awake pairs' warm starts: a pass, which a step makes anyway; the sleeping ones: only those
  // of the removed bodies' contacts (every other keeps its key, so nothing is renamed or turned).
  dropRemoved(cache_, removed);
  indexCache();
  for (const std::uint64_t key : goneAsleep) asleepCache_.erase(key);
}

const SoftStepSolver::Cached* SoftStepSolver::cached(std::uint64_t key) const {
  const std::optional<std::uint32_t> at = cacheIndex_.find(key);
  return at ? &cache_[*at] : nullptr;
}

void SoftStepSolver::indexCache() {
  cacheIndex_.reset(cache_.size());
  for (std::size_t i = 0; i < cache_.size(); ++i) cacheIndex_.insert(cache_[i].key, static_cast<std::uint32_t>(i));
}

void SoftStepSolver::prepare(const std::vector<RigidBody>& bodies, const Contact& contact, std::size_t index,
                             std::uint64_t key, const Material& material, const Settings& settings) {
  const bool plane = contact.kind == Contact::Kind::PlaneBody;
  const ContactManifold& m = contact.manifold;
  Constraint c;
  c.a = plane ? 0 : slotOfBody_[contact.a];
  c.b = slotOfBody_[contact.b];
  c.normal = m.normal;
  tangentBasis(c.normal, c.tangent1, c.tangent2);
  c.restitution = material.restitution;
  c.softness = softness_;
  c.firstPoint = points_.size();
  c.pointCount = static_cast<std::size_t>(m.count);
  c.contact = index;
  c.key = key;
  const Cached* old = settings.warmStarting ? cached(c.key) : nullptr;
  // A new manifold first assumes sticking (seed 000); a known one keeps the regime its last step
  // ended in: sliding when friction reached the cone, sticking again when it stayed inside.
  c.sticking = old == nullptr || old->sticking;
  c.staticFriction = material.staticFriction;
  c.kineticFriction = material.kineticFriction;

  const Vec3 xA = sims_[c.a].position0, xB = sims_[c.b].position0;
  const BodySim& simA = sims_[c.a];
  const BodySim& simB = sims_[c.b];
  const SolverState& stateA = states_[c.a];
  const SolverState& stateB = states_[c.b];
  const Vec3& n = c.normal;
  const std::array<Vec3, 2> tangents{c.tangent1, c.tangent2};
  // The normal acceleration the applied forces give the pair, for the speed at which the
  // surfaces meet within the step (restitution).
  const double normalAcceleration = n.dot(simB.acceleration - simA.acceleration);
  c.normalAcceleration = normalAcceleration;
  // A round side's surface point lies r - depth / 2 from its core along the normal
  // (collision/narrowphase/shape_pairs.h puts the point midway between the surfaces); -1: not round.
  const auto roundRadius = [&](int slot, std::uint16_t child) {
    if (slot == 0) return -1.0;
    const RigidBody& body = bodies[sims_[slot].body];
    const Shape& shape = body.isCompound() ? body.children()[child].shape : body.shape();
    return shape.isRound() ? shape.radius : -1.0;
  };
  const double radiusA = roundRadius(c.a, contact.childA), radiusB = roundRadius(c.b, contact.childB);
  bool collides = false, collisionSlides = false;
  for (int i = 0; i < m.count; ++i) {
    Point p;
    PointFrame f;
    PointReport r;
    const Vec3& position = m.points[i].position;
    const double separation = -m.points[i].depth;
    r.position = position;
    r.depth = m.points[i].depth;
    // The ground's slot never moves, so its anchors are their own body-frame coordinates.
    // Each body's copy of the point: one point for a manifold computed this step, the kept arms'
    // for a recycled one (ContactPoint::offset).
    const Vec3 offset = m.points[i].offset;
    Vec3 pointA = position - 0.5 * offset, pointB = position + 0.5 * offset;
    // A round side's copy of a speculative point (s > 0) is its own surface point: the surfaces
    // meet there within the step, and a copy halfway across the gap would stay s / 2 beyond the
    // surface, the lever arm of the impact's friction (a ball 35 mm above the ground spun 17 %
    // too fast). Its core is R from it.
    const double gap = 0.5 * std::max(separation, 0.0), inside = 0.5 * std::min(separation, 0.0);
    if (radiusA >= 0.0) {
      f.roundA = (radiusA + inside) * n;
      pointA -= gap * n;
    }
    if (radiusB >= 0.0) {
      f.roundB = -(radiusB + inside) * n;
      pointB += gap * n;
    }
    f.split = !offset.isZero(0.0);
    f.localA = c.a == 0 ? pointA : Vec3(stateA.orientation.conjugate() * (pointA - f.roundA - xA));
    f.localB = c.b == 0 ? pointB : Vec3(stateB.orientation.conjugate() * (pointB - f.roundB - xB));
    f.baseSeparation = separation - n.dot((pointB - xB) - (pointA - xA));
    updateArms(c, f, p, /*masses=*/true);
    r.relativeVelocity = normalVelocity(c, p, stateA, stateB);
    // Energy of the normal motion from the step's start to the touch: u^2 = u0^2 - 2 a_n s0.
    if (r.relativeVelocity < 0.0) {
      const double squared = r.relativeVelocity * r.relativeVelocity - 2.0 * normalAcceleration * std::max(separation, 0.0);
      r.impactSpeed = std::sqrt(std::max(squared, 0.0));
    }
    if (old != nullptr) {
      for (int j = 0; j < old->count; ++j) {
        if ((old->localPoints[j] - f.localB).norm() <= settings.warmStartDistance) {
          p.normalImpulse = old->normalImpulses[j];
          p.tangentImpulse = {tangents[0].dot(old->frictionImpulses[j]), tangents[1].dot(old->frictionImpulses[j])};
          r.sliding = old->sliding[j];
          break;
        }
      }
    }
    // At a collision both models take seed 000's regime for the impact: kinetic when the
    // impulse that stops the slip leaves the mu_s cone of the whole impact (Coulomb's law for one
    // impulse), whatever the contact did before.
    if (const std::optional<bool> slides = seedSlides(p.anchorA, p.anchorB, c, stateA, stateB, material, settings)) {
      r.sliding = *slides;
      collides = true;
      collisionSlides = collisionSlides || *slides;
    }
    points_.push_back(p);
    frames_.push_back(f);
    reports_.push_back(r);
  }
  if (collides) c.sticking = !collisionSlides;  // the cone's regime is the patch's
  constraints_.push_back(c);
}

std::optional<bool> SoftStepSolver::seedSlides(const Vec3& anchorA, const Vec3& anchorB, const Constraint& c,
                                               const SolverState& stateA, const SolverState& stateB,
                                               const Material& material, const Settings& settings) const {
  const Vec3 u = stateB.linearVelocity + stateB.angularVelocity.cross(anchorB) - stateA.linearVelocity -
                 stateA.angularVelocity.cross(anchorA);  // u_rel, body 1 = B
  if (u.dot(c.normal) >= -settings.restitutionThreshold) return std::nullopt;  // resting, not a collision
  const Mat3 factor = impulseFactor(sims_[c.a].inverseMass, sims_[c.a].inverseInertiaNow, anchorA) +
                      impulseFactor(sims_[c.b].inverseMass, sims_[c.b].inverseInertiaNow, anchorB);
  const CollisionImpulse hit = collisionImpulse<3>(factor, u, c.normal, material);
  return hit.colliding && !hit.sticking;
}

void SoftStepSolver::updateArms(const Constraint& c, const PointFrame& f, Point& p, bool masses) const {
  // Both bodies' impulses act at one world point, midway between where each body now carries its
  // anchor (Point::anchorA).
  const SolverState& A = states_[c.a];
  const SolverState& B = states_[c.b];
  const Pose& poseA = poses_[c.a];
  const Pose& poseB = poses_[c.b];
  const Vec3& xA = poseA.position;
  const Vec3& xB = poseB.position;
  const Vec3 onA = poseA.rotation * f.localA + f.roundA, onB = poseB.rotation * f.localB + f.roundB;
  // A round body against a flat one (the ground, or a box, whose copy is a material point of
  // it) takes the impulse where it carries the point: the other copy stays where the step began
  // on it, and halfway to it would put the force behind a ball rolling on, a torque that is not
  // there; before the touch it is the ball's own surface point, the impact's lever arm R. (Two
  // flat or two round sides keep the midpoint, whose lag of half a step's slide the box suites
  // are measured with.)
  Vec3 point = 0.5 * (xA + onA + xB + onB);
  const bool roundA = !f.roundA.isZero(0.0), roundB = !f.roundB.isZero(0.0);
  if (roundB && !roundA) point = xB + onB;
  if (roundA && !roundB) point = xA + onA;
  // The separation now, from the anchors carried by the bodies (no collision detection within
  // the step; Box2D v3's comment at the top of contact_solver.c).
  p.separation = f.baseSeparation + c.normal.dot(B.deltaPosition - A.deltaPosition + onB - onA);
  p.anchorA = point - xA;
  p.anchorB = point - xB;
  if (f.split) {  // a recycled point: each body pushes at its own kept arm, as Box3D's anchors
    p.anchorA = onA;
    p.anchorB = onB;
  }
  if (!masses) return;
  const Mat3& iA = sims_[c.a].inverseInertiaNow;
  const Mat3& iB = sims_[c.b].inverseInertiaNow;
  const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
  const Vec3 crossA = p.anchorA.cross(c.normal), crossB = p.anchorB.cross(c.normal);
  // n^T K n with K = (1/m) 1 + r*^T I^-1 r* summed over the pair (seed 000).
  p.normalMass = 1.0 / (mA + mB + crossA.dot(iA * crossA) + crossB.dot(iB * crossB));
  const std::array<Vec3, 2> tangents{c.tangent1, c.tangent2};
  std::array<Vec3, 2> tA, tB, fA, fB;  // r x t_k, I^-1 (r x t_k)
  for (int k = 0; k < 2; ++k) {
    tA[k] = p.anchorA.cross(tangents[k]);
    tB[k] = p.anchorB.cross(tangents[k]);
    fA[k] = iA * tA[k];
    fB[k] = iB * tB[k];
    p.tangentMass[k] = 1.0 / (mA + mB + tA[k].dot(fA[k]) + tB[k].dot(fB[k]));
  }
  p.tangentCoupling = tA[0].dot(fA[1]) + tB[0].dot(fB[1]);  // t1 . t2 = 0
}

void SoftStepSolver::integrateVelocities(double h) {
  parallelFor(states_.size() - 1, threads_, [&](std::size_t k) {
    const std::size_t i = k + 1;
    states_[i].linearVelocity += h * sims_[i].acceleration;
    states_[i].angularVelocity += h * (sims_[i].inverseInertiaNow * sims_[i].torque);
  });
}

void SoftStepSolver::warmStart(std::size_t island) {
  islands_.forContacts(island, [&](std::size_t index) {
    const Constraint& c = constraints_[index];
    SolverState& A = states_[c.a];
    SolverState& B = states_[c.b];
    for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
      const Point& p = points_[j];
      applyImpulse(c, p, p.normalImpulse * c.normal + p.tangentImpulse[0] * c.tangent1 + p.tangentImpulse[1] * c.tangent2, A, B);
    }
  });
}

// The normal rows of one constraint, point by point, on the pair's velocities (both sweeps, the
// cone's and seed 000's friction, share them).
void SoftStepSolver::solveNormals(Constraint& c, double inverseH, const Settings& settings, bool useBias, bool lastRelax,
                                  Vec3& vA, Vec3& wA, Vec3& vB, Vec3& wB) {
  const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
  const Mat3& iA = sims_[c.a].inverseInertiaNow;
  const Mat3& iB = sims_[c.b].inverseInertiaNow;
  const Vec3& n = c.normal;
  for (std::size_t k = 0; k < c.pointCount; ++k) {
    Point& p = points_[c.firstPoint + k];
    const Vec3 crossA = p.anchorA.cross(n), crossB = p.anchorB.cross(n);
    const double s = p.separation;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (s > 0.0) {
      bias = s * inverseH;  // speculative: the gap may close within the substep, no further
    } else if (useBias) {
      bias = std::max(c.softness.biasRate * s, -settings.contactPushSpeed);
      massScale = c.softness.massScale;
      impulseScale = c.softness.impulseScale;
    }
    const double vn = n.dot(vB - vA) + crossB.dot(wB) - crossA.dot(wA);
    // A bouncing approach still short of the surface when the step ends keeps its speed: the
    // next step's first substep holds it to the gap all the same, and by then its prepare has
    // taken the speed at the touch for restitution. Held here, a ball dropped at dt = 1/60 s
    // reached the ground at 3.15 of its 4.42 m/s and rebounded to half the height e = 1 asks
    // for (examples/python/restitution_sweep.py); a box dropped flat 1 m left at 93 % of c_R u_c
    // and spun up to 26 rad/s on landing (0.35 rad/s kept for patches too; issue 36).
    // A single point's fast approach belongs to the collision pass at the next substep's start
    // (collide): slowed here to close the gap exactly, it met the surface at a fraction of its
    // speed and bounced with that fraction (a ball 49 mm above the ground at 1/240 s left at
    // 0.3 of its 1.5 m/s).
    if (s > 0.0 && c.restitution > 0.0 && -vn > settings.restitutionThreshold && (lastRelax || c.pointCount == 1)) continue;
    const double impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
    // Accumulated and kept repulsive (seed 001: f_i >= 0).
    const double total = std::max(p.normalImpulse + impulse, 0.0);
    const double delta = total - p.normalImpulse;
    p.normalImpulse = total;
    // Pushing within the slop of touching: the surfaces met (a speculative point lands a body
    // at s = 0 up to rounding, so s <= 0 alone can miss it).
    if (total > 0.0 && s <= settings.contactSlop) c.touched = true;
    vA -= (mA * delta) * n;
    wA -= iA * (delta * crossA);
    vB += (mB * delta) * n;
    wB += iB * (delta * crossB);
  }
}

void SoftStepSolver::solve(std::size_t island, double inverseH, const Settings& settings, bool useBias, bool lastRelax) {
  const Settings::FrictionModel model = settings.friction;
  islands_.forContacts(island, [&](std::size_t index) {
    Constraint& c = constraints_[index];
    // The relax is the first sweep after the positions moved: it brings the arms and separations
    // to the new poses as it reaches each constraint, for itself, the next substep's warm start
    // and solve, and the restitution pass (a pass of its own over every point cost 12 % of the
    // pyramid's step, most of it reading and writing the points twice).
    if (!useBias) {
      for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) updateArms(c, frames_[j], points_[j], false);
    }
    SolverState& A = states_[c.a];
    SolverState& B = states_[c.b];
    const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
    const Mat3& iA = sims_[c.a].inverseInertiaNow;
    const Mat3& iB = sims_[c.b].inverseInertiaNow;
    Vec3 vA = A.linearVelocity, wA = A.angularVelocity, vB = B.linearVelocity, wB = B.angularVelocity;
    const Vec3& n = c.normal;
    // Non-penetration first, friction with the new normal impulses after (Box2D v3's order).
    solveNormals(c, inverseH, settings, useBias, lastRelax, vA, wA, vB, wB);
    bool sticking = true;
    for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
      Point& p = points_[j];
      const Vec3& rA = p.anchorA;
      const Vec3& rB = p.anchorB;
      const Vec3 slip = vB + wB.cross(rB) - vA - wA.cross(rA);  // u_rel, body 1 = B
      FrictionPoint point;
      point.accumulated = {p.tangentImpulse[0], p.tangentImpulse[1]};
      point.slip = {c.tangent1.dot(slip), c.tangent2.dot(slip)};
      point.tangentMass = {p.tangentMass[0], p.tangentMass[1]};
      point.coupling = p.tangentCoupling;
      point.normalImpulse = p.normalImpulse;
      point.staticFriction = c.staticFriction;
      point.kineticFriction = c.kineticFriction;
      // The cone's regime is the patch's, seed 000's each point's (friction_law.h).
      point.sliding = model == Settings::FrictionModel::Seed000 ? reports_[j].sliding : !c.sticking;
      const FrictionImpulse next = frictionImpulse(model, point);
      sticking = sticking && next.sticking;
      const double d0 = next.total[0] - p.tangentImpulse[0], d1 = next.total[1] - p.tangentImpulse[1];
      p.tangentImpulse = {next.total[0], next.total[1]};
      const Vec3 impulse = d0 * c.tangent1 + d1 * c.tangent2;
      vA -= mA * impulse;
      wA -= iA * rA.cross(impulse);
      vB += mB * impulse;
      wB += iB * rB.cross(impulse);
      if (!useBias) {  // a relax ends the substep: what it leaves is what the substep applied
        reports_[j].totalNormalImpulse += p.normalImpulse;
        reports_[j].totalFriction += p.tangentImpulse[0] * c.tangent1 + p.tangentImpulse[1] * c.tangent2;
      }
    }
    if (lastRelax) {
      // Seed 000's regimes decided by the slip the step ends with: a patch slipping faster than
      // kSlidingSpeed slides (mu_k) next step, a slower one sticks (mu_s). Deciding by which
      // points reached their cone would flip a patch that sticks as a whole to sliding whenever
      // the load is uneven across its points. Seed 000's law keeps each point's regime as well.
      double slip = 0.0;
      for (std::size_t j = c.firstPoint; j < c.firstPoint + c.pointCount; ++j) {
        const Point& p = points_[j];
        const Vec3 v = vB + wB.cross(p.anchorB) - vA - wA.cross(p.anchorA);
        const double pointSlip = (v - v.dot(n) * n).norm();
        reports_[j].sliding = pointSlip > kSlidingSpeed;
        slip = std::max(slip, pointSlip);
      }
      c.slipping = slip > kSlidingSpeed && (model == Settings::FrictionModel::Cone || !sticking);
    }
    storeVelocities(c.a, vA, wA);
    storeVelocities(c.b, vB, wB);
  });
}

void SoftStepSolver::integratePositions(double h) {
  parallelFor(states_.size() - 1, threads_, [&](std::size_t k) {
    const std::size_t i = k + 1;
    SolverState& s = states_[i];
    BodySim& sim = sims_[i];
    s.deltaPosition += h * s.linearVelocity;
    poses_[i].position = sim.position0 + s.deltaPosition;
    if (sim.kinematic) {  // turns at its prescribed omega, which no impulse changes
      s.orientation = expMapStep(s.orientation, s.angularVelocity, h);
      poses_[i].rotation = s.orientation.toRotationMatrix();
      return;
    }
    // The rotation by angle |omega| h (seed 004's alternative), with L = I omega carried over:
    // free rotation keeps L, so omega follows the new orientation (the gyroscopic term of
    // Euler's equations, which a fixed omega would drop).
    const Mat3 R = s.orientation.toRotationMatrix();
    const Vec3 L = R * (inertias_[i].inertia * (R.transpose() * s.angularVelocity));
    s.orientation = expMapStep(s.orientation, s.angularVelocity, h);
    const Mat3 next = s.orientation.toRotationMatrix();
    poses_[i].rotation = next;
    sim.inverseInertiaNow = next * inertias_[i].inverse * next.transpose();
    s.angularVelocity = sim.inverseInertiaNow * L;
  });
}

void SoftStepSolver::solve(const SolverInput& input) {
  std::vector<RigidBody>& bodies = input.bodies;
  const std::vector<Contact>& contacts = input.contacts;
  std::vector<Joint>& joints = input.joints;
  const Settings& settings = input.settings;
  const bool addGravity = input.addGravity;
  clearAdvanced();
  advanced_.resize(bodies.size(), 0);
  slotOfBody_.resize(bodies.size(), 0);
  states_.assign(1, SolverState{});
  sims_.assign(1, BodySim{});
  inertias_.assign(1, BodyInertia{});
  poses_.assign(1, Pose{});
  constraints_.clear();
  points_.clear();
  frames_.clear();
  reports_.clear();
  solved_.clear();
  hits_.clear();
  hitSpeed_ = settings.hitEventSpeed;
  reported_ = true;
  joints_.clear();

  const double h = settings.timeStep / settings.substeps;
  const double hertz = std::min(settings.contactHertz, kMaxHertzPerSubstepRate / h);
  softness_ = makeSoftness(hertz, settings.contactDampingRatio, h);

  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& contact = contacts[i];
    const bool plane = contact.kind == Contact::Kind::PlaneBody;
    // A sleeping pair receives nothing (World wakes an island an awake body touches), and keeps
    // its impulses for the step it wakes, as Box2D's sleeping solver sets keep theirs.
    const bool awake = bodies[contact.b].awake() || (!plane && bodies[contact.a].awake());
    if (contact.manifold.count == 0) continue;
    if (!awake) {
      if (const Cached* old = cached(pairKey(contact, input.bodyIds.slotOfItem()))) nextCache_.push_back(*old);
      continue;
    }
    slot(bodies, contact.b, settings, addGravity);
    if (!plane) slot(bodies, contact.a, settings, addGravity);
  }
  slotJoints(bodies, input.bodyIds, joints, settings, addGravity);
  prepareJoints(bodies, input.bodyIds, joints, settings);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& contact = contacts[i];
    const bool plane = contact.kind == Contact::Kind::PlaneBody;
    if (contact.manifold.count == 0) continue;
    const int b = slotOfBody_[contact.b], a = plane ? 0 : slotOfBody_[contact.a];
    if (a == 0 && b == 0) continue;  // asleep, or static against static
    if (sims_[a].inverseMass == 0.0 && sims_[b].inverseMass == 0.0) continue;  // kinematic against static
    const Material material = contactMaterial(input, contact);
    prepare(bodies, contact, i, pairKey(contact, input.bodyIds.slotOfItem()), material, settings);
  }

  bouncing_.clear();
  for (std::size_t i = 0; i < constraints_.size(); ++i) {
    if (constraints_[i].pointCount == 1 && constraints_[i].restitution > 0.0) bouncing_.push_back(i);
  }
  threads_ = settings.threads;
  islands_.build(
      states_.size(), constraints_.size(), [&](std::size_t i) { return constraints_[i].a; },
      [&](std::size_t i) { return constraints_[i].b; }, joints_.size(), [&](std::size_t i) { return joints_[i].base; },
      [&](std::size_t i) { return joints_[i].moving; });
  const double inverseH = 1.0 / h;
  for (int substep = 0; substep < settings.substeps; ++substep) {
    const bool last = substep == settings.substeps - 1;
    integrateVelocities(h);
    collide(settings, h);
    forEachIsland([&](std::size_t island) {
      warmStartJoints(island);
      warmStart(island);  // the last substep's impulses (at the first, the last step's, when kept)
      solveJoints(island, h, /*useBias=*/true);
      solve(island, inverseH, settings, /*useBias=*/true, /*lastRelax=*/false);
    });
    integratePositions(h);  // the relax then moves the arms and separations with the bodies
    forEachIsland([&](std::size_t island) {
      solveJoints(island, h, /*useBias=*/false);
      solve(island, inverseH, settings, /*useBias=*/false, /*lastRelax=*/last);
    });
  }
  applyRestitution(settings);
  finish(bodies);
}

}  // namespace rbsim
