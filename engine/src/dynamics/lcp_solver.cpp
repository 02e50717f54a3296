#include "dynamics/lcp_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "dynamics/contact_key.h"
#include "rbsim/dynamics/impulse.h"
#include "rbsim/integrate/integrator.h"
#include "rbsim/integrate/simulation_error.h"
#include "math/disjoint_sets.h"

namespace rbsim {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// How every message of this solver starts: the scene key that chose it.
const std::string kLcpSolverKey = "world.solver \"lcp\": ";

}  // namespace

int LcpSolver::solverBody(const SolverInput& input, std::size_t body) {
  const RigidBody& b = input.bodies[body];
  if (b.isStatic()) return 0;
  int& slot = slotOfBody_[body];
  if (slot != 0) return slot;
  slot = static_cast<int>(bodies_.size());
  if (b.isKinematic()) {
    // Infinite mass (seed 000's K = 0), its prescribed velocity in the relative one; the World's
    // integrator moves it as prescribed.
    bodies_.push_back(SolverBody{0.0, Mat3::Zero(), body});
    velocities_.push_back(Velocity{b.velocity(), b.angularVelocity()});
    return slot;
  }
  // Velocities first, with the step's forces (Catto 2005's order; the soft step's substep):
  // P += dt (F + m g), L += dt (tau + R tau_body), omega = I^-1 L at the step's orientation.
  const double dt = input.settings.timeStep;
  const Vec3 acceleration = b.force() / b.mass() + (input.addGravity ? input.settings.gravity : Vec3::Zero());
  const Vec3 angularMomentum = b.state().angularMomentum + dt * (b.torque() + b.rotation() * b.bodyTorque());
  bodies_.push_back(SolverBody{1.0 / b.mass(), b.inverseInertiaWorld(), body});
  velocities_.push_back(
      Velocity{b.velocity() + dt * acceleration, bodies_.back().inverseInertiaWorld * angularMomentum});
  advanced_[body] = 1;
  advancedList_.push_back(body);
  return slot;
}

void LcpSolver::bodiesRemoved(const std::vector<std::uint32_t>& removed,
                              const std::vector<std::uint64_t>& /*goneAsleep: its cache holds every warm start*/) {
  clearAdvanced();
  solved_.clear();
  dropRemoved(cache_, removed);
}

double LcpSolver::normalVelocity(const Row& row, const std::vector<Velocity>& velocities) const {
  // u_rel,N = N . (v1 + omega1 x r1 - v2 - omega2 x r2) (seed 000), (omega x r) . n = omega . (r x n).
  const Velocity& v1 = velocities[row.body1];
  const Velocity& v2 = velocities[row.body2];
  return row.normal.dot(v1.linear - v2.linear) + row.angular1.dot(v1.angular) - row.angular2.dot(v2.angular);
}

void LcpSolver::applyNormal(const Row& row, double impulse, std::vector<Velocity>& velocities) const {
  // Seed 002 2.2.1: dP = j, dL = r x j; body 2 receives the opposite at the same point.
  velocities[row.body1].linear += (bodies_[row.body1].inverseMass * impulse) * row.normal;
  velocities[row.body1].angular += impulse * row.angularStep1;
  velocities[row.body2].linear -= (bodies_[row.body2].inverseMass * impulse) * row.normal;
  velocities[row.body2].angular -= impulse * row.angularStep2;
}

void LcpSolver::applyFriction(const Patch& patch, const Vec3& impulse) {
  // The tangential impulse at the centroid and the angular impulse about n (seed 002 2.2.1).
  const Vec3 linear = impulse.x() * patch.tangent1 + impulse.y() * patch.tangent2;
  velocities_[patch.body1].linear += bodies_[patch.body1].inverseMass * linear;
  velocities_[patch.body1].angular += patch.angularStep1 * impulse;
  velocities_[patch.body2].linear -= bodies_[patch.body2].inverseMass * linear;
  velocities_[patch.body2].angular -= patch.angularStep2 * impulse;
}

void LcpSolver::buildPatch(const SolverInput& input, const Contact& contact, std::size_t index) {
  const std::vector<RigidBody>& bodies = input.bodies;
  const Settings& settings = input.settings;
  const Material material = contactMaterial(input, contact);
  const double dt = settings.timeStep;
  const bool plane = contact.kind == Contact::Kind::PlaneBody;
  const ContactManifold& m = contact.manifold;
  Patch patch;
  patch.body1 = solverBody(input, contact.b);
  patch.body2 = plane ? 0 : solverBody(input, contact.a);
  patch.normal = m.normal;
  tangentBasis(patch.normal, patch.tangent1, patch.tangent2);
  patch.material = material;
  patch.firstRow = rows_.size();
  patch.rowCount = static_cast<std::size_t>(m.count);
  patch.key = pairKey(contact, input.bodyIds.slotOfItem());
  const RigidBody& b1 = bodies[contact.b];
  const Vec3 x2 = plane ? Vec3::Zero() : bodies[contact.a].position();
  const SolverBody& s1 = bodies_[patch.body1];
  const SolverBody& s2 = bodies_[patch.body2];
  const Vec3& n = patch.normal;

  // Where each point acts, as PGS places it (pgs_solver.cpp, buildPatch, which says why): the
  // manifold's point, except that a round side touching a flat one at a single point takes it on
  // its own surface.
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
  // A known manifold keeps the regime its last step ended in, a new one first assumes sticking
  // (seed 000 "Friction"); its friction, in this step's tangent plane, is the first guess.
  const auto found = std::lower_bound(cache_.begin(), cache_.end(), patch.key,
                                      [](const Cached& c, std::uint64_t key) { return c.key < key; });
  const Cached* known = found != cache_.end() && found->key == patch.key ? &*found : nullptr;
  patch.sticking = known == nullptr || known->sticking;
  if (known != nullptr) {
    const Vec3 linear = known->linearFriction - known->linearFriction.dot(n) * n;
    patch.friction = Vec3(linear.dot(patch.tangent1), linear.dot(patch.tangent2), known->twistFriction);
  }

  for (int i = 0; i < m.count; ++i) {
    Row row;
    row.body1 = patch.body1;
    row.body2 = patch.body2;
    row.normal = n;
    const Vec3 r1 = points[i] - b1.position();
    const Vec3 r2 = plane ? Vec3::Zero() : Vec3(points[i] - x2);
    row.angular1 = r1.cross(n);
    row.angular2 = r2.cross(n);
    row.angularStep1 = s1.inverseInertiaWorld * row.angular1;
    row.angularStep2 = s2.inverseInertiaWorld * row.angular2;
    // The target: seed 000's u_rel,N^new = -c_R u_rel,N (seed 001 "Colliding contact") for a point
    // approaching faster than the restitution threshold that reaches the surface within the step
    // (a speculative one reverses up to |u| dt short of it); otherwise a speculative point may
    // close its gap within the step, a touching one not at all.
    const double approach = normalVelocity(row, velocities_);
    const double gap = -m.points[i].depth;
    const bool collides =
        material.restitution > 0.0 && approach < -settings.restitutionThreshold && -approach * dt >= gap;
    row.target = collides ? -material.restitution * approach : -std::max(gap, 0.0) / dt;
    row.correction = std::max(0.0, settings.positionCorrection * (-gap - settings.contactSlop) / dt);
    // Last step's point within the warm-start distance, in body 1's frame (as PGS's warm start).
    row.localPoint1 = b1.rotation().transpose() * r1;
    for (int j = 0; known != nullptr && j < known->count; ++j) {
      if ((known->localPoints[j] - row.localPoint1).norm() <= settings.warmStartDistance) {
        row.clamped = known->clamped[j];
        break;
      }
    }
    SolvedContactPoint out;
    out.contact = index;
    out.position = points[i];
    out.normal = n;
    out.depth = m.points[i].depth;
    out.approachVelocity = approach;
    rows_.push_back(row);
    solved_.push_back(out);
  }
  patches_.push_back(patch);
}

double LcpSolver::solveFriction(Patch& patch) {
  double normalTotal = 0.0;
  for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) normalTotal += rows_[r].impulse;
  const Velocity& v1 = velocities_[patch.body1];
  const Velocity& v2 = velocities_[patch.body2];
  // PGS's cone (PgsSolver::solveFriction): the impulse that stops the slip along t1, t2 at the
  // centroid and the twist about n, cut onto the cone of mu_s while sticking, mu_k while sliding.
  const Vec3 dv = v1.linear - v2.linear;
  const Vec3 w = Vec3(dv.dot(patch.tangent1), dv.dot(patch.tangent2), 0.0) +
                 patch.angular1.transpose() * v1.angular - patch.angular2.transpose() * v2.angular;
  const Vec3 candidate = patch.friction - patch.inverseFriction * w;
  const double mu = patch.sticking ? patch.material.staticFriction : patch.material.kineticFriction;
  const double limit = mu * normalTotal;
  const double slipImpulse = candidate.head<2>().norm();
  patch.insideCone = slipImpulse <= limit && std::abs(candidate.z()) <= limit * patch.twistRadius;
  Vec3 total = candidate;
  if (slipImpulse > limit) total.head<2>() *= limit / slipImpulse;
  total.z() = std::clamp(candidate.z(), -limit * patch.twistRadius, limit * patch.twistRadius);
  const Vec3 change = total - patch.friction;
  applyFriction(patch, change);
  patch.friction = total;
  return change.head<2>().norm() + (patch.twistRadius > 0.0 ? std::abs(change.z()) / patch.twistRadius : 0.0);
}

MatrixXd LcpSolver::delassus(const std::vector<std::size_t>& rows) {
  // A_ij = J_i M^-1 J_j^T, a sum over the dynamic bodies rows i and j share, each term
  // s_i s_j (n_i . n_j / m + (r_i x n_i) . I^-1 (r_j x n_j)), s = +1 on body 1 and -1 on body 2
  // (seed 001's a_ij, here per unit impulse: the change of u_rel,N at i per unit j_N at j).
  const Index n = static_cast<Index>(rows.size());
  MatrixXd a = MatrixXd::Zero(n, n);
  bodyRows_.resize(bodies_.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& row = rows_[rows[k]];
    if (bodies_[row.body1].inverseMass > 0.0) bodyRows_[row.body1].push_back({k, 1.0});
    if (bodies_[row.body2].inverseMass > 0.0) bodyRows_[row.body2].push_back({k, -1.0});
  }
  for (std::size_t slot = 1; slot < bodyRows_.size(); ++slot) {
    for (const auto& [i, si] : bodyRows_[slot]) {
      const Row& ri = rows_[rows[i]];
      const Vec3& angular = si > 0.0 ? ri.angular1 : ri.angular2;
      for (const auto& [j, sj] : bodyRows_[slot]) {
        const Row& rj = rows_[rows[j]];
        const Vec3& step = sj > 0.0 ? rj.angularStep1 : rj.angularStep2;
        a(static_cast<Index>(i), static_cast<Index>(j)) +=
            si * sj * (bodies_[slot].inverseMass * ri.normal.dot(rj.normal) + angular.dot(step));
      }
    }
    bodyRows_[slot].clear();
  }
  return 0.5 * (a + a.transpose());  // symmetric to the last bit, as lcp_pivoting.h assumes
}

LcpSolution LcpSolver::solveExactly(const MatrixXd& a, const std::vector<std::size_t>& rows, double Row::*field,
                                    double Row::*target, std::vector<Velocity>& velocities,
                                    const std::vector<char>* guess, bool leastNorm) {
  // b: the normal velocities without this field's impulses (the current ones less A f_old), less
  // the targets; the LCP's w is then each row's velocity after the solve above its target.
  const Index n = static_cast<Index>(rows.size());
  VectorXd b(n), old(n);
  for (Index k = 0; k < n; ++k) {
    const Row& row = rows_[rows[static_cast<std::size_t>(k)]];
    b(k) = normalVelocity(row, velocities) - row.*target;
    old(k) = row.*field;
  }
  b -= a * old;
  LcpSolution solution = solveLcp(a, b, guess, leastNorm);
  if (solution.status != LcpSolution::Status::Solved) return solution;
  for (Index k = 0; k < n; ++k) {
    Row& row = rows_[rows[static_cast<std::size_t>(k)]];
    applyNormal(row, solution.f(k) - old(k), velocities);
    row.*field = solution.f(k);
  }
  return solution;
}

void LcpSolver::solveIsland(const std::vector<std::size_t>& rows, const std::vector<std::size_t>& patches,
                            const std::string& body) {
  const std::string island =
      "an island of " + std::to_string(rows.size()) + " contact points (body '" + body + "' among them)";
  largestIsland_ = std::max(largestIsland_, rows.size());
  if (rows.size() > kMaxLcpRows) {
    throw SimulationError(kLcpSolverKey + island + " is more than kMaxLcpRows = " + std::to_string(kMaxLcpRows) +
                          " rows of a dense pivoting solve; expected a smaller scene, or world.solver \"pgs\" or "
                          "\"soft-step\"");
  }
  const MatrixXd a = delassus(rows);
  const auto solved = [&](const LcpSolution& solution, const char* what) {
    pivots_ += solution.pivots;
    if (solution.status == LcpSolution::Status::NoSolution) {
      throw SimulationError(kLcpSolverKey + "the " + what + " of " + island +
                            " have no solution: a body is pressed between static or kinematic ones");
    }
    if (solution.status == LcpSolution::Status::PivotLimit) {
      throw SimulationError(kLcpSolverKey + "the pivoting took more than kMaxLcpPivotsPerRow = " +
                            std::to_string(kMaxLcpPivotsPerRow) + " pivots per row for the " + what + " of " + island);
    }
    return solution.clamped;
  };
  // Last step's friction first (where there is friction), and last step's pushing points as the
  // guess.
  const bool friction = std::any_of(patches.begin(), patches.end(), [&](std::size_t p) {
    return patches_[p].material.staticFriction > 0.0 || patches_[p].material.kineticFriction > 0.0;
  });
  for (std::size_t p : patches) {
    if (!friction) patches_[p].friction = Vec3::Zero();
    applyFriction(patches_[p], patches_[p].friction);
  }
  std::vector<char> clamped(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) clamped[k] = rows_[rows[k]].clamped;
  const auto normal = [&](bool leastNorm) {
    clamped = solved(solveExactly(a, rows, &Row::impulse, &Row::target, velocities_, &clamped, leastNorm),
                     "normal impulses");
  };
  normal(!friction);
  // Friction with the normal impulses held, then the normal impulses exactly for that friction,
  // until the friction settles (lcp_solver.h); sweeps alternate direction, as PGS's. The
  // least-norm choice among the normal solutions (a decomposition of A_ZZ) is made once, last.
  int passes = 0;
  const double never = std::numeric_limits<double>::infinity();
  std::array<double, 2> before{never, never};  // the changes of the last two passes
  for (int pass = 0; friction && pass < kMaxLcpFrictionPasses; ++pass) {
    ++passes;
    double largestNormal = 0.0, change = 0.0;
    for (std::size_t r : rows) largestNormal = std::max(largestNormal, rows_[r].impulse);
    for (std::size_t k = 0; k < patches.size(); ++k) {
      change = std::max(change, solveFriction(patches_[patches[pass % 2 == 0 ? k : patches.size() - 1 - k]]));
    }
    normal(false);
    // Settled, or at rounding's floor: no smaller a change than two passes before (the sweeps
    // alternate, so rounding alternates with them).
    if (change <= kLcpFrictionTolerance * largestNormal || change >= before[0]) break;
    before = {before[1], change};
  }
  if (friction) normal(true);
  frictionPasses_ = std::max(frictionPasses_, passes);
  for (std::size_t k = 0; k < rows.size(); ++k) rows_[rows[k]].clamped = clamped[k];
  // Split impulses (Catto, GDC 2009): pseudo-velocities w = A p - c >= 0 for the correction
  // speeds c, with the same A; they move the bodies and are forgotten. A body wedged too deep
  // between fixed ones cannot be pushed out of both: then nothing is corrected this step (the
  // velocities, seed 001's problem, are solved already).
  const bool penetrates =
      std::any_of(rows.begin(), rows.end(), [&](std::size_t r) { return rows_[r].correction > 0.0; });
  if (penetrates) {
    pivots_ += solveExactly(a, rows, &Row::pseudoImpulse, &Row::correction, pseudoVelocities_, nullptr, false).pivots;
  }
}

void LcpSolver::writeBack(std::vector<RigidBody>& bodies, double dt) {
  // Positions with the new velocities, and the split impulse's pseudo-velocities, which move the
  // body out of penetration over this step and are then forgotten (never kinetic energy). The
  // rotation by angle |omega| dt keeps L = I omega: free rotation keeps L, so omega follows the
  // new orientation (the gyroscopic term), as the soft step's substep does.
  for (std::size_t i = 1; i < bodies_.size(); ++i) {
    RigidBody& body = bodies[bodies_[i].body];
    if (body.isKinematic()) continue;  // moves as prescribed: the World's integrator moves it
    const Velocity& v = velocities_[i];
    const Velocity& pseudo = pseudoVelocities_[i];
    const Mat3 r = body.rotation();
    BodyState state = body.state();
    state.linearMomentum = body.mass() * v.linear;
    state.angularMomentum = r * (body.inertiaBody() * (r.transpose() * v.angular));
    state.position += dt * (v.linear + pseudo.linear);
    state.orientation = expMapStep(state.orientation, v.angular + pseudo.angular, dt).normalized();
    body.setState(state);
    body.clearAccumulators();
  }
}

void LcpSolver::solve(const SolverInput& input) {
  std::vector<RigidBody>& bodies = input.bodies;
  const std::vector<Contact>& contacts = input.contacts;
  const Settings& settings = input.settings;
  bodies_.assign(1, SolverBody{});
  velocities_.assign(1, Velocity{});
  slotOfBody_.assign(bodies.size(), 0);  // whole, so that a step that threw leaves nothing behind
  clearAdvanced();
  advanced_.resize(bodies.size(), 0);
  patches_.clear();
  rows_.clear();
  solved_.clear();
  pivots_ = 0;
  frictionPasses_ = 0;
  largestIsland_ = 0;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const Contact& contact = contacts[c];
    const bool plane = contact.kind == Contact::Kind::PlaneBody;
    // A sleeping pair receives nothing (World wakes the sleeping side of a pair with an awake one).
    const bool awake = bodies[contact.b].awake() || (!plane && bodies[contact.a].awake());
    if (contact.manifold.count > 0 && awake) buildPatch(input, contact, c);
  }
  pseudoVelocities_.assign(bodies_.size(), Velocity{});

  // Islands: bodies of finite mass linked by their contacts (math/disjoint_sets.h); a patch between
  // two bodies of infinite mass moves nothing and gets no impulse.
  const auto dynamic = [&](int slot) { return bodies_[static_cast<std::size_t>(slot)].inverseMass > 0.0; };
  DisjointSets islands(bodies_.size());
  for (const Patch& patch : patches_) {
    if (dynamic(patch.body1) && dynamic(patch.body2)) islands.link(patch.body1, patch.body2);
  }
  std::vector<int> islandOf(bodies_.size(), -1);
  std::vector<std::vector<std::size_t>> islandRows, islandPatches;
  std::vector<std::size_t> islandBody;
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const Patch& patch = patches_[p];
    if (!dynamic(patch.body1) && !dynamic(patch.body2)) continue;
    const std::size_t root = islands.find(static_cast<std::size_t>(dynamic(patch.body1) ? patch.body1 : patch.body2));
    if (islandOf[root] < 0) {
      islandOf[root] = static_cast<int>(islandRows.size());
      islandRows.emplace_back();
      islandPatches.emplace_back();
      islandBody.push_back(bodies_[root].body);
    }
    const auto k = static_cast<std::size_t>(islandOf[root]);
    islandPatches[k].push_back(p);
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) islandRows[k].push_back(r);
  }
  for (std::size_t k = 0; k < islandRows.size(); ++k) {
    solveIsland(islandRows[k], islandPatches[k], bodies[islandBody[k]].name());
  }

  for (const Patch& patch : patches_) {
    double normalTotal = 0.0;
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) normalTotal += rows_[r].impulse;
    const Vec3 friction = patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2;
    for (std::size_t r = patch.firstRow; r < patch.firstRow + patch.rowCount; ++r) {
      SolvedContactPoint& out = solved_[r];
      out.normalImpulse = rows_[r].impulse;
      out.frictionImpulse = normalTotal > 0.0 ? Vec3(friction * (rows_[r].impulse / normalTotal)) : Vec3::Zero();
      out.normalVelocity = normalVelocity(rows_[r], velocities_);
      out.sticking = patch.sticking && patch.insideCone;
    }
  }
  writeBack(bodies, settings.timeStep);
  cache_.clear();
  for (const Patch& patch : patches_) {
    Cached c{patch.key, patch.insideCone, patch.friction.x() * patch.tangent1 + patch.friction.y() * patch.tangent2,
             patch.friction.z(), static_cast<int>(patch.rowCount)};
    for (std::size_t i = 0; i < patch.rowCount; ++i) {
      c.localPoints[i] = rows_[patch.firstRow + i].localPoint1;
      c.clamped[i] = rows_[patch.firstRow + i].clamped;
    }
    cache_.push_back(c);
  }
  std::sort(cache_.begin(), cache_.end(), [](const Cached& a, const Cached& b) { return a.key < b.key; });
}

}  // namespace rbsim
