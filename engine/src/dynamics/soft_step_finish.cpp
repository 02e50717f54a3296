// What the soft step does after its substeps (soft_step_solver.h): the restitution pass, the
// points reported to the World, the impulses kept for the next step's warm start, and the new
// state written back to the bodies.
#include <algorithm>
#include <cmath>

#include "dynamics/friction_law.h"
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

void SoftStepSolver::collide(const Settings& settings, double h) {
  // Seed 000 "Collision": u_rel,N^new = -c_R u_rel,N, one point at a time, each with the
  // velocities the points before it left, and swept until nothing approaches (Guendelman,
  // Bridson, Fedkiw 2003, "Nonconvex rigid bodies with stacking", collision processing before
  // contact processing): a ball hitting a row of touching balls hands its momentum on pair by
  // pair, as Newton's cradle does, where one simultaneous solve would move the row together.
  // Only pairs touching at one point: a patch (a box landing flat) bounces in applyRestitution,
  // whose sweeps share the rebound among its points instead of tipping it at the first one.
  // The collision takes seed 000's whole impulse, friction included (collisionImpulse,
  // dynamics/impulse.h), as the seed writes it for one collision, with either friction model.
  if (bouncing_.empty()) return;
  for (int sweep = 0; sweep < kCollisionSweeps; ++sweep) {
    bool collided = false;
    for (const std::size_t index : bouncing_) {
      const Constraint& c = constraints_[index];
      Point& p = points_[c.firstPoint];
      SolverState& A = states_[c.a];
      SolverState& B = states_[c.b];
      const Vec3& n = c.normal;
      const double vn = normalVelocity(c, p, A, B);
      // Slower approaches are resting contact; a gap the approach does not close within this
      // substep is left for a later one. A collision within the substep is taken at its start,
      // with the speed the substep moves at, up to |u| h short of the touch: met by the soft
      // contacts instead, the impact's first part stopped the ball as an inelastic push spread
      // over the bodies it touches (Newton's cradle hit mid-step passed 0.52 of the speed on),
      // and its bounce came after the substeps without the friction the seed gives it.
      if (-vn <= settings.restitutionThreshold || p.separation + vn * h > kTouchingGap) continue;
      // Taken s above the surface, the bounce leaves with the speed that carries it as far as
      // c_R times the speed at the touch would, leave^2 = (c_R u_c)^2 + 2 a_N s (PGS does the
      // same): c_R u from there gave a c_R = 0.3 ball dropped 1 cm at 1/60 s 29 % too much. The
      // speed at the touch is the one prepare found from the energy at the step's start (a
      // substep's velocity leads it by up to g h); for a pair set moving within the step, as a
      // cradle's next ball is, u_c^2 = u^2 - 2 a_N s. Where the bounce would not carry it back
      // up here, it goes on to the surface and bounces there. This substep's kick of the applied
      // forces, already in u, is kept on top of the bounce: replaced by it, each bounce at 1/60 s
      // gained g h |u| (a ball with c_R = 1 rose 7 mm over its 1 m).
      PointReport& report = reports_[c.firstPoint];
      const double gap = std::max(p.separation, 0.0), kick = c.normalAcceleration * h;
      const double touch = report.impactSpeed > 0.0 ? report.impactSpeed * report.impactSpeed
                                                    : (vn - kick) * (vn - kick) - 2.0 * c.normalAcceleration * gap;
      const double leave = c.restitution * c.restitution * touch + 2.0 * c.normalAcceleration * gap;
      if (leave < 0.0) continue;
      const double away = std::sqrt(leave) + kick;  // u_rel,N after the collision
      if (away <= 0.0) continue;
      report.impactSpeed = 0.0;  // it has bounced: applyRestitution must not bounce it again
      collided = true;
      // Seed 000 "Friction", literally: the whole impulse of the collision from the 3x3 K_T,
      // sticking if inside the mu_s cone, kinetic (N - mu_k T) j_n otherwise. Coulomb's law
      // for one impulse, so the cone takes it too (the models part in resting and sliding
      // contact, friction_law.h).
      const double mA = sims_[c.a].inverseMass, mB = sims_[c.b].inverseMass;
      const Mat3& iA = sims_[c.a].inverseInertiaNow;
      const Mat3& iB = sims_[c.b].inverseInertiaNow;
      const Vec3& rA = p.anchorA;
      const Vec3& rB = p.anchorB;
      const Vec3 u = B.linearVelocity + B.angularVelocity.cross(rB) - A.linearVelocity -
                     A.angularVelocity.cross(rA);  // u_rel, body 1 = B
      const CollisionImpulse hit = collisionImpulse<3>(impulseFactor(mA, iA, rA) + impulseFactor(mB, iB, rB), u, n,
                                                       Material{away / -vn, c.staticFriction, c.kineticFriction});
      const Vec3& j = hit.impulse;
      report.totalNormalImpulse += j.dot(n);
      report.totalFriction += j - j.dot(n) * n;
      report.sliding = !hit.sticking;  // the regime the substeps carry on with
      applyImpulse(c, p, j, A, B);
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
        PointReport& report = reports_[j];
        report.totalNormalImpulse += delta;
        applyImpulse(c, p, delta * n, A, B);
        // The bounce is the impact's last part, and friction acts with it: the substeps gave
        // the part that stopped the approach its mu j_n, and without this the rebound's c_R of it
        // slid free (a ball hitting the ground mid-step at 12 m/s left at 11.4 instead of seed
        // 000's 11.1 m/s). Same law, same regime, the bounce's impulse as its normal impulse.
        report.bounceImpulse += delta;
        FrictionPoint point;
        point.accumulated = report.bounceFriction;
        const Vec3 slip = B.linearVelocity + B.angularVelocity.cross(p.anchorB) - A.linearVelocity -
                          A.angularVelocity.cross(p.anchorA);
        point.slip = {c.tangent1.dot(slip), c.tangent2.dot(slip)};
        point.tangentMass = {p.tangentMass[0], p.tangentMass[1]};
        point.coupling = p.tangentCoupling;
        point.normalImpulse = report.bounceImpulse;
        point.staticFriction = c.staticFriction;
        point.kineticFriction = c.kineticFriction;
        point.sliding = settings.friction == Settings::FrictionModel::Seed000 ? report.sliding : !c.sticking;
        const Eigen::Vector2d next = frictionImpulse(settings.friction, point).total;
        const Eigen::Vector2d change = next - report.bounceFriction;
        report.bounceFriction = next;
        p.tangentImpulse[0] += change[0];
        p.tangentImpulse[1] += change[1];
        const Vec3 friction = change[0] * c.tangent1 + change[1] * c.tangent2;
        report.totalFriction += friction;
        applyImpulse(c, p, friction, A, B);
      }
    }
  }
}

void SoftStepSolver::report() const {
  solved_.clear();
  for (const Constraint& c : constraints_) {
    if (c.contact == kNotReported) continue;
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
    ContactHit hit{c.contact, Vec3::Zero(), hitSpeed_};
    for (std::size_t j = 0; j < c.pointCount; ++j) {
      const Point& p = points_[c.firstPoint + j];
      const PointReport& r = reports_[c.firstPoint + j];
      cache.localPoints[j] = frames_[c.firstPoint + j].localB;
      cache.normalImpulses[j] = p.normalImpulse;
      cache.sliding[j] = r.sliding;
      cache.frictionImpulses[j] = p.tangentImpulse[0] * c.tangent1 + p.tangentImpulse[1] * c.tangent2;
      // A hit (ContactSolver::hits): here, where the report is read anyway, costs no pass of its own.
      if (-r.relativeVelocity > hit.approachSpeed && r.totalNormalImpulse > 0.0) {
        hit.approachSpeed = -r.relativeVelocity;
        hit.point = r.position;
      }
    }
    if (hit.approachSpeed > hitSpeed_) hits_.push_back(hit);
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

void SoftStepSolver::contactsSlept(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys) {
  std::vector<std::uint64_t> slept;
  slept.reserve(contacts.size());
  for (const Contact& c : contacts) {
    const std::uint64_t key = pairKey(c, bodyKeys);
    if (const Cached* old = cached(key)) {
      asleepCache_[key] = *old;
      slept.push_back(key);
    }
  }
  if (slept.empty()) return;
  // They leave cache_, which then holds the awake pairs' alone: a removal filters it whole.
  std::sort(slept.begin(), slept.end());
  cache_.erase(std::remove_if(cache_.begin(), cache_.end(),
                              [&](const Cached& e) { return std::binary_search(slept.begin(), slept.end(), e.key); }),
               cache_.end());
  indexCache();
}

void SoftStepSolver::contactsReindexed(const std::vector<std::uint32_t>& newIndex) {
  if (reported_) {
    reindexPoints(solved_, newIndex);
  } else {  // the report is built from the constraints when asked: those of slept contacts leave it
    for (Constraint& c : constraints_) c.contact = c.contact == kNotReported ? kNotReported : newIndex[c.contact];
  }
  std::size_t kept = 0;
  for (ContactHit& hit : hits_) {
    if (newIndex[hit.contact] == kDroppedContact) continue;
    hit.contact = newIndex[hit.contact];
    hits_[kept++] = hit;
  }
  hits_.resize(kept);
}

void SoftStepSolver::contactsWoke(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys) {
  bool added = false;
  for (const Contact& c : contacts) {
    const auto at = asleepCache_.find(pairKey(c, bodyKeys));
    if (at == asleepCache_.end()) continue;
    if (!cached(at->first)) {
      cache_.push_back(at->second);
      added = true;
    }
    asleepCache_.erase(at);
  }
  if (!added) return;
  std::sort(cache_.begin(), cache_.end(), [](const Cached& a, const Cached& b) { return a.key < b.key; });
  indexCache();
}

void SoftStepSolver::mergeAsleep(std::vector<Cached>& into) const {
  if (asleepCache_.empty()) return;
  // The kept ones sorted by key (a hash map has no order; only a snapshot asks), then one merge
  // with `into`, a key in both taken once (from `into`).
  std::vector<const Cached*> asleep;
  asleep.reserve(asleepCache_.size());
  for (const auto& [key, entry] : asleepCache_) asleep.push_back(&entry);
  std::sort(asleep.begin(), asleep.end(), [](const Cached* x, const Cached* y) { return x->key < y->key; });
  std::vector<Cached> merged;
  merged.reserve(into.size() + asleep.size());
  auto a = into.begin();
  for (const Cached* entry : asleep) {
    while (a != into.end() && a->key < entry->key) merged.push_back(*a++);
    if (a != into.end() && a->key == entry->key) continue;
    merged.push_back(*entry);
  }
  merged.insert(merged.end(), a, into.end());
  into.swap(merged);
}

}  // namespace rbsim
