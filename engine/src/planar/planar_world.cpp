#include "rbsim/planar/planar_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "rbsim/integrate/simulation_error.h"

namespace rbsim {

namespace {

// The reference edge stays on polygon a unless b's axis separates by more than this fraction of
// the slop: equal axes (a box resting flat on another) would otherwise swap from step to step.
constexpr double kReferenceBias = 1e-3;  // [1] of contactSlop

Vec2 outwardNormal(const std::vector<Vec2>& corners, std::size_t edge) {
  const Vec2 d = corners[(edge + 1) % corners.size()] - corners[edge];
  return Vec2(d.y(), -d.x()).normalized();  // counter-clockwise polygons
}

// Separating axis test over the edge normals of `a`: the largest separation of b from one of a's
// edges (< 0 when they overlap along every normal of a), and that edge.
std::pair<double, std::size_t> maxSeparation(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double best = -std::numeric_limits<double>::infinity();
  std::size_t bestEdge = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 n = outwardNormal(a, i);
    double deepest = std::numeric_limits<double>::infinity();
    for (const Vec2& q : b) deepest = std::min(deepest, n.dot(q - a[i]));
    if (deepest > best) {
      best = deepest;
      bestEdge = i;
    }
  }
  return {best, bestEdge};
}

bool orderContacts(const PlanarContact& a, const PlanarContact& b) {
  return std::tie(a.body, a.other, a.againstLine, a.feature) < std::tie(b.body, b.other, b.againstLine, b.feature);
}

std::vector<Vec2> worldCorners(const PlanarBody& b) {
  std::vector<Vec2> corners;
  for (std::size_t i = 0; i < b.polygon().size(); ++i) corners.push_back(b.corner(i));
  return corners;
}

struct Row {
  double normalMass = 0.0, tangentMass = 0.0;
  double targetNormalVelocity = 0.0, correctionVelocity = 0.0;
  double pseudoImpulse = 0.0;
  Vec2 r1 = Vec2::Zero(), r2 = Vec2::Zero();
  Material material;
};

}  // namespace

PlanarWorld::PlanarWorld(const PlanarSettings& settings) : settings_(settings) {
  if (!(settings.timeStep > 0.0) || !(settings.timeStep <= 0.1)) {
    throw std::invalid_argument("planar world: expected 0 < dt <= 0.1 s");
  }
}

std::size_t PlanarWorld::addBody(const PlanarBody& body) {
  bodies_.push_back(body);
  return bodies_.size() - 1;
}

void PlanarWorld::addLine(const PlanarLine& line) {
  if (std::abs(line.normal.norm() - 1.0) > kUnitTolerance) throw std::invalid_argument("planar line: expected a unit normal");
  lines_.push_back(line);
}

void PlanarWorld::collidePolygons(std::size_t i, std::size_t j, const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  // The axis of least penetration among both polygons' edge normals (SAT) gives the reference
  // edge; the other polygon's edge facing it most is clipped to the reference edge's slab and its
  // points behind the edge (or within the margin) are the contacts (as Box2D Lite's box-box).
  const auto [separationA, edgeA] = maxSeparation(a, b);
  const auto [separationB, edgeB] = maxSeparation(b, a);
  if (std::max(separationA, separationB) > settings_.contactMargin) return;
  const bool referenceIsA = separationA >= separationB - kReferenceBias * settings_.contactSlop;
  const std::vector<Vec2>& reference = referenceIsA ? a : b;
  const std::vector<Vec2>& incident = referenceIsA ? b : a;
  const std::size_t edge = referenceIsA ? edgeA : edgeB;
  const Vec2 n = outwardNormal(reference, edge);
  std::size_t facing = 0;
  double mostAgainst = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < incident.size(); ++k) {
    const double along = outwardNormal(incident, k).dot(n);
    if (along < mostAgainst) {
      mostAgainst = along;
      facing = k;
    }
  }
  const Vec2 p1 = reference[edge], p2 = reference[(edge + 1) % reference.size()];
  const Vec2 t = (p2 - p1).normalized();
  Vec2 v1 = incident[facing], v2 = incident[(facing + 1) % incident.size()];
  // Clip the incident edge to t . (v - p1) >= 0 and t . (v - p2) <= 0.
  const auto clip = [](Vec2& from, Vec2& to, const Vec2& axis, double limit) {
    const double df = axis.dot(from) - limit, dt = axis.dot(to) - limit;
    if (df > 0.0 && dt > 0.0) return false;
    if (df > 0.0) from = from + (to - from) * (df / (df - dt));
    if (dt > 0.0) to = to + (from - to) * (dt / (dt - df));
    return true;
  };
  if (!clip(v1, v2, -t, -t.dot(p1)) || !clip(v1, v2, t, t.dot(p2))) return;
  const std::size_t body = referenceIsA ? j : i, other = referenceIsA ? i : j;
  const Vec2 ends[2] = {v1, v2};
  for (int k = 0; k < 2; ++k) {
    const double depth = -n.dot(ends[k] - p1);
    if (depth >= -settings_.contactMargin) contacts_.push_back({body, other, false, k, ends[k], n, depth});
  }
}

void PlanarWorld::detect() {
  contacts_.clear();
  std::vector<std::vector<Vec2>> corners;
  for (const PlanarBody& b : bodies_) corners.push_back(worldCorners(b));
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    for (std::size_t l = 0; l < lines_.size(); ++l) {
      const PlanarLine& line = lines_[l];
      for (const Vec2& p : corners[i]) {
        const double depth = line.offset - line.normal.dot(p);
        const int corner = static_cast<int>(&p - corners[i].data());
        if (depth >= -settings_.contactMargin) contacts_.push_back({i, l, true, corner, p, line.normal, depth});
      }
    }
    for (std::size_t j = i + 1; j < bodies_.size(); ++j) collidePolygons(i, j, corners[i], corners[j]);
  }
}

void PlanarWorld::solve() {
  const double dt = settings_.timeStep;
  std::vector<Row> rows(contacts_.size());
  std::vector<Vec2> pseudoVelocity(bodies_.size(), Vec2::Zero());
  std::vector<double> pseudoAngular(bodies_.size(), 0.0);
  const auto inverseMass = [&](std::size_t b) { return 1.0 / bodies_[b].mass(); };
  const auto inverseInertia = [&](std::size_t b) { return 1.0 / bodies_[b].inertia(); };
  const auto relativeVelocity = [&](const PlanarContact& c) {
    Vec2 u = bodies_[c.body].pointVelocity(c.point);
    if (!c.againstLine) u -= bodies_[c.other].pointVelocity(c.point);
    return u;
  };
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const PlanarContact& c = contacts_[k];
    Row& row = rows[k];
    row.r1 = c.point - bodies_[c.body].state().position;
    Mat2 factor = planarImpulseFactor(inverseMass(c.body), inverseInertia(c.body), row.r1);
    if (!c.againstLine) {
      row.r2 = c.point - bodies_[c.other].state().position;
      factor += planarImpulseFactor(inverseMass(c.other), inverseInertia(c.other), row.r2);
    }
    const Vec2 tangent(-c.normal.y(), c.normal.x());
    row.normalMass = 1.0 / c.normal.dot(factor * c.normal);
    row.tangentMass = 1.0 / tangent.dot(factor * tangent);
    row.material = combine(bodies_[c.body].material(),
                           c.againstLine ? lines_[c.other].material : bodies_[c.other].material());
    const double approach = relativeVelocity(c).dot(c.normal);
    const double gap = -c.depth;
    const bool bounces = approach < -settings_.restitutionThreshold && -approach * dt >= gap;
    row.targetNormalVelocity = bounces ? -row.material.restitution * approach : -std::max(gap, 0.0) / dt;
    row.correctionVelocity = std::max(0.0, settings_.positionCorrection * (c.depth - settings_.contactSlop) / dt);
  }
  const auto apply = [&](const PlanarContact& c, const Vec2& impulse) {
    bodies_[c.body].applyImpulse(impulse, c.point);
    if (!c.againstLine) bodies_[c.other].applyImpulse(-impulse, c.point);
  };
  // Warm start: the same point of the same pair starts from last step's impulses.
  for (PlanarContact& c : contacts_) {
    const auto it = std::lower_bound(previous_.begin(), previous_.end(), c, orderContacts);
    if (it != previous_.end() && !orderContacts(c, *it)) {
      c.normalImpulse = it->normalImpulse;
      c.tangentImpulse = it->tangentImpulse;
      apply(c, c.normalImpulse * c.normal + c.tangentImpulse * Vec2(-c.normal.y(), c.normal.x()));
    }
  }
  for (int sweep = 0; sweep < settings_.velocityIterations; ++sweep) {
    // Alternate directions (symmetric Gauss-Seidel), as the 3D solver: one-way sweeps favour
    // the rows visited last and walk a stack sideways.
    for (std::size_t visit = 0; visit < contacts_.size(); ++visit) {
      const std::size_t k = sweep % 2 == 0 ? visit : contacts_.size() - 1 - visit;
      PlanarContact& c = contacts_[k];
      const Row& row = rows[k];
      const Vec2 tangent(-c.normal.y(), c.normal.x());
      // Coulomb friction in the cone of this sweep's normal impulse (kinetic coefficient: a
      // point's regime is not tracked in 2D).
      const double slip = relativeVelocity(c).dot(tangent);
      const double limit = row.material.kineticFriction * c.normalImpulse;
      const double tangentTotal = std::clamp(c.tangentImpulse - row.tangentMass * slip, -limit, limit);
      apply(c, (tangentTotal - c.tangentImpulse) * tangent);
      c.tangentImpulse = tangentTotal;
      const double u = relativeVelocity(c).dot(c.normal);
      const double normalTotal = std::max(0.0, c.normalImpulse + row.normalMass * (row.targetNormalVelocity - u));
      apply(c, (normalTotal - c.normalImpulse) * c.normal);
      c.normalImpulse = normalTotal;
    }
  }
  for (int sweep = 0; sweep < settings_.positionIterations; ++sweep) {
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      const PlanarContact& c = contacts_[k];
      Row& row = rows[k];
      double u = (pseudoVelocity[c.body] + cross2(pseudoAngular[c.body], row.r1)).dot(c.normal);
      if (!c.againstLine) u -= (pseudoVelocity[c.other] + cross2(pseudoAngular[c.other], row.r2)).dot(c.normal);
      const double total = std::max(0.0, row.pseudoImpulse + row.normalMass * (row.correctionVelocity - u));
      const Vec2 j = (total - row.pseudoImpulse) * c.normal;
      row.pseudoImpulse = total;
      pseudoVelocity[c.body] += inverseMass(c.body) * j;
      pseudoAngular[c.body] += inverseInertia(c.body) * cross2(row.r1, j);
      if (!c.againstLine) {
        pseudoVelocity[c.other] -= inverseMass(c.other) * j;
        pseudoAngular[c.other] -= inverseInertia(c.other) * cross2(row.r2, j);
      }
    }
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].state().position += dt * pseudoVelocity[b];
    bodies_[b].state().angle += dt * pseudoAngular[b];
  }
  previous_ = contacts_;
  std::sort(previous_.begin(), previous_.end(), orderContacts);
}

void PlanarWorld::step() {
  // Velocities first (gravity and forces), then contacts at the current positions, then
  // positions with the solved velocities: the semi-implicit order of the 3D World.
  const double dt = settings_.timeStep;
  for (PlanarBody& b : bodies_) {
    PlanarState& s = b.state();
    s.linearMomentum += dt * b.mass() * settings_.gravity;
  }
  detect();
  if (contacts_.empty()) {
    previous_.clear();
  } else {
    solve();
  }
  for (PlanarBody& b : bodies_) {
    const Vec2 velocity = b.velocity();
    const double spin = b.angularVelocity();
    b.step(dt, Vec2::Zero());
    const PlanarState& s = b.state();
    std::string lost;
    const auto add = [&lost](bool finite, const char* what) {
      if (!finite) lost += (lost.empty() ? "" : ", ") + std::string(what);
    };
    add(s.position.allFinite(), "position");
    add(std::isfinite(s.angle), "angle");
    add(s.linearMomentum.allFinite(), "linear momentum");
    add(std::isfinite(s.angularMomentum), "angular momentum");
    if (!lost.empty()) {
      std::ostringstream message;
      message << "planar body '" << b.name() << "': " << lost << " stopped being finite at step " << steps_
              << " (t = " << time() << " s, dt = " << dt << " s). Before the step: |v| = " << velocity.stableNorm()
              << " m/s, omega = " << spin << " rad/s, m = " << b.mass() << " kg, I = " << b.inertia()
              << " kg m^2. Likely a velocity, mass or contact impulse beyond what the semi-implicit step can carry.";
      throw SimulationError(message.str());
    }
  }
  ++steps_;
}

}  // namespace rbsim
