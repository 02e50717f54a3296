#include "world/collision_pipeline.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

#include "collision/narrowphase/box_box.h"
#include "collision/narrowphase/convex_convex.h"
#include "collision/narrowphase/convex_plane.h"
#include "collision/narrowphase/mesh_mesh.h"
#include "collision/narrowphase/sdf_contact.h"
#include "shapes/implicit_shape.h"
#include "collision/narrowphase/shape_pairs.h"
#include "world/compound_contacts.h"
#include "world/mesh_ground_contacts.h"
#include "world/continuous_collision.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/math/parallel.h"

namespace rbsim {

namespace {

// A plane's manifold is taken from the vertices within the body's reach in the step (|v| dt +
// |omega| r dt + |g| dt^2) of the deepest, plus this [m]: above a resting face's rounding and
// solver noise (0.1 mm), below a grid bevel's rise (half a cell, centimetres).
constexpr double kPlaneSupportSlack = 1e-3;

// The lowest point of a box along -n is its support point: the box is below the plane's
// margin band exactly when that point is.
bool aabbNearPlane(const Aabb& box, const Plane& plane, double margin) {
  const Vec3 lowest((plane.normal.x() > 0.0 ? box.min : box.max).x(), (plane.normal.y() > 0.0 ? box.min : box.max).y(),
                    (plane.normal.z() > 0.0 ? box.min : box.max).z());
  return plane.signedDistance(lowest) <= margin;
}

// An implicit body's samples in world frame, in a buffer of the calling thread's, and the exact
// surface's point deepest below the plane near the deepest sample (ImplicitSolid::supportNear).
const std::vector<Vec3>& implicitPlaneCandidates(const RigidBody& body, const BodySolid& solid, const Plane& plane) {
  thread_local std::vector<Vec3> world;
  const std::vector<Vec3>& samples = *solid.samples;
  world.resize(samples.size());
  const Mat3& R = body.rotation();
  std::size_t deepest = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    world[k] = R * samples[k] + body.position();
    if (plane.signedDistance(world[k]) < plane.signedDistance(world[deepest])) deepest = k;
  }
  if (!samples.empty()) {
    const Vec3 down = -(R.transpose() * plane.normal);
    world.push_back(R * solid.implicit->supportNear(samples[deepest], down, solid.sdf->cellSize()) + body.position());
  }
  return world;
}

PosedMesh posedMesh(const RigidBody& body, const BodySolid& solid) {
  return {&body.mesh(), solid.triangles.get(), body.rotation(), body.position()};
}

PosedShape posed(const RigidBody& body) { return {&body.shape(), body.rotation(), body.position()}; }

// A hull's face planes where it is; none for a box (its SAT has its own) or a grid body's hull.
PosedFaces facesOf(const RigidBody& body) { return {body.shape().faces.get(), body.rotation(), body.position()}; }

// A hull large enough that GJK climbs its vertex graph rather than scanning it.
bool climbs(const RigidBody& body) {
  const Shape& s = body.shape();
  return s.type == ShapeType::ConvexHull && s.hull->vertices.size() > kHillClimbMinVertices;
}

// The body's collision shape (a compound's children), not its display mesh: continuous_collision.h.
SweptBody sweptOf(const RigidBody& body, const BodyState& start, double radius) {
  return SweptBody{&body.shape(), &body.children(), start, body.state(), radius};
}

}  // namespace

CollisionPipeline::CollisionPipeline(const Settings& settings, BodyTable& table)
    : settings_(settings),
      table_(&table),
      broad_(std::make_unique<SplitBroadPhase>(settings.broadPhase)),
      sleeping_(table.keptContacts),
      log_(settings.queryLogCapacity) {}

CollisionPipeline::CollisionPipeline(const CollisionPipeline& other, BodyTable& table)
    : settings_(other.settings_),
      table_(&table),
      broad_(std::make_unique<SplitBroadPhase>(*other.broad_)),
      bodyOfProxy_(other.bodyOfProxy_),
      fastList_(other.fastList_),
      haveStart_(other.haveStart_),
      ignored_(other.ignored_),
      ignoredSorted_(other.ignoredSorted_),
      contacts_(other.contacts_),
      sleeping_(other.sleeping_, table.keptContacts),
      sleptNow_(other.sleptNow_),
      pairSlots_(other.pairSlots_),
      planeSlots_(other.planeSlots_),
      pairFrames_(other.pairFrames_),
      planeFrames_(other.planeFrames_),
      keptPairFrames_(other.keptPairFrames_),
      keptPlaneFrames_(other.keptPlaneFrames_),
      recycle_(other.recycle_),
      recycledCount_(other.recycledCount_),
      recycleTolerance_(other.recycleTolerance_),
      later_(other.later_),
      compoundSlots_(other.compoundSlots_),
      compoundPlaneSlots_(other.compoundPlaneSlots_),
      compoundWork_(other.compoundWork_),
      impacts_(other.impacts_),
      log_(other.log_) {}

bool CollisionPipeline::needsBroadPhase(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes) const {
  if (table_->size() < 2 && planes.empty()) return false;
  return !awake.empty();
}

void CollisionPipeline::rememberStart(const std::vector<std::uint32_t>& awake) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  // A sleeping body does not move in the step: its start is where it is (continuous reads it so).
  for (const std::uint32_t i : awake) table_->start[i] = bodies[i].state();
  haveStart_ = true;
}

bool CollisionPipeline::isFast(std::size_t body) const { return table_->fast[body] != 0; }

void CollisionPipeline::continuous(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes,
                                   const std::vector<char>* solved) {
  std::vector<RigidBody>& bodies = table_->bodies;  // a fast body is moved back to its impact
  impacts_.clear();
  for (const std::size_t i : fastList_) table_->fast[i] = 0;
  fastList_.clear();
  for (const std::size_t i : awake) {
    const RigidBody& body = bodies[i];
    // A kinematic body goes where it is told, through anything: it is never stopped. A body with a
    // grid is swept too, as its convex hull, which holds it: it may stop a little early (at its
    // hull's touch, where the grid's contacts take over), never late. Its partners with grids
    // are not swept against (a ball falling into a bowl would stop at the bowl's hull).
    if (!body.awake() || !haveStart_ || body.isKinematic()) continue;
    // Stopping a body the solver moved would undo its speculative contacts, which already hold
    // it at the surfaces it can reach this step (and hold it still, again, every step after).
    if (solved != nullptr && i < solved->size() && (*solved)[i] != 0) continue;
    const double motion = motionBound(sweptOf(body, table_->start[i], table_->radius[i]));
    if (motion > settings_.ccdMotionFraction * table_->thickness[i]) {
      table_->fast[i] = 1;
      fastList_.push_back(i);
    }
  }
  if (fastList_.empty()) {
    haveStart_ = false;
    return;
  }
  // Each body's box over its whole step (last step's box, which covers the start pose, grown by
  // the end pose), computed once, before any body is moved back: a contact during the step lies
  // inside both bodies' boxes. A sleeping or static body's is its box.
  stepBoxes_.resize(bodies.size());
  for (const std::size_t j : awake) {
    stepBoxes_[j] = table_->boxes[j];
    stepBoxes_[j].grow(bodyBounds(bodies[j]));
  }
  const auto stepBox = [&](std::size_t j) -> const Aabb& { return bodies[j].awake() ? stepBoxes_[j] : table_->boxes[j]; };
  for (const std::size_t i : fastList_) {
    const SweptBody swept = sweptOf(bodies[i], table_->start[i], table_->radius[i]);
    double first = 1.0;
    for (const Plane& plane : planes) {
      if (const auto s = timeOfImpact(swept, plane)) first = std::min(first, *s);
    }
    Aabb sweep = boundsAt(swept, 0.0);
    sweep.grow(boundsAt(swept, 1.0));
    nearSweep(sweep, awake, near_);
    for (const std::size_t j : near_) {
      if (j == i || table_->hasGrid[j] || !sweep.overlaps(stepBox(j))) continue;
      const SweptBody partner = sweptOf(bodies[j], bodies[j].awake() ? table_->start[j] : bodies[j].state(), table_->radius[j]);
      if (const auto s = timeOfImpact(swept, partner)) first = std::min(first, *s);
    }
    if (first < 1.0) {
      impacts_.push_back({i, first, bodies[i].position(), bodies[i].orientation()});
      bodies[i].setState(poseAt(swept, first));  // momenta kept: the response is the solver's
    }
  }
  haveStart_ = false;
}

void CollisionPipeline::broadPhase(const std::vector<std::uint32_t>& awake) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  // Each awake body's box on any thread, then into the broad phase in body order.
  parallelFor(awake.size(), settings_.threads, [&](std::size_t k) {
    const std::size_t i = awake[k];
    Aabb box = bodyBounds(bodies[i]);
    if (isFast(i)) box.grow(boundsAt(sweptOf(bodies[i], table_->start[i], table_->radius[i]), 0.0));
    const double dt = settings_.timeStep;
    table_->reach[i] = dt * (bodies[i].velocity().norm() + bodies[i].angularVelocity().norm() * table_->radius[i] +
                      dt * settings_.gravity.norm());
    table_->boxes[i] = box.inflated(settings_.contactMargin + table_->gap[i] + table_->reach[i]);
  });
  for (const std::size_t i : awake) {
    // A finite state can still have a box that is not (a vertex R p + x or a reach dt |v|
    // overflows): that is the body diverging, reported as such rather than as a broad-phase fault.
    if (!table_->boxes[i].min.allFinite() || !table_->boxes[i].max.allFinite()) {
      std::ostringstream message;
      message << "body '" << bodies[i].name() << "': its bounding box stopped being finite (|x| = "
              << bodies[i].position().stableNorm() << " m, |v| = " << bodies[i].velocity().stableNorm() << " m/s)";
      throw SimulationError(message.str());
    }
    broad_->move(table_->proxies[i], table_->boxes[i]);
  }
  awakeProxies_.clear();
  for (const std::size_t i : awake) awakeProxies_.push_back(table_->proxies[i]);
  broad_->update(awakeProxies_);
}

void CollisionPipeline::setIgnoredPairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  ignored_.clear();
  for (auto [a, b] : pairs) {
    if (a > b) std::swap(a, b);
    ignored_.push_back((std::uint64_t{a} << 32) | std::uint64_t{b});
  }
  std::sort(ignored_.begin(), ignored_.end());
  ignoredSorted_ = true;
}

void CollisionPipeline::ignorePair(std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  ignored_.push_back((std::uint64_t{a} << 32) | std::uint64_t{b});
  ignoredSorted_ = false;
}

ProxyPair CollisionPipeline::bodiesOf(const ProxyPair& proxies) const {
  const std::vector<std::uint32_t>& keys = table_->keys();
  // A destroyed body's index goes to the last body, whose proxy id stays as it was.
  ProxyPair pair{static_cast<ProxyId>(bodyOfProxy_[proxies.a]), static_cast<ProxyId>(bodyOfProxy_[proxies.b])};
  if (keys[pair.a] > keys[pair.b]) std::swap(pair.a, pair.b);
  return pair;
}

CollisionPipeline::Later CollisionPipeline::collidePair(const ProxyPair& proxies, double time, Contact& out,
                                                       RecycleFrame& frame) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const std::vector<BodySolid>& shapes = table_->solids;
  out.manifold.count = 0;
  const ProxyPair pair = bodiesOf(proxies);
  if (!ignored_.empty() && std::binary_search(ignored_.begin(), ignored_.end(),
                                              (std::uint64_t{std::min(pair.a, pair.b)} << 32) | std::max(pair.a, pair.b))) {
    return Later::Nothing;
  }
  const RigidBody& a = bodies[pair.a];
  const RigidBody& b = bodies[pair.b];
  // A compound's children are filtered one by one (compound_contacts.h, mesh_ground_contacts.h).
  const bool compound = a.isCompound() || b.isCompound();
  const bool ground = table_->meshGround[pair.a] || table_->meshGround[pair.b];
  if (!compound && !ground && !shouldCollide(a.filter(), b.filter())) return Later::Nothing;
  // Both asleep (a pair the broad phase listed before they slept): their contact is kept apart
  // with their island's (keepSleeping).
  if (!a.awake() && !b.awake()) return Later::Nothing;
  // Static and kinematic bodies pass through each other: both have infinite mass (seed 000's
  // K = 0), so no impulse could separate them.
  if (!a.isDynamic() && !b.isDynamic()) return Later::Nothing;
  // Before the grid's test: a body with a grid meets a mesh ground as its convex hull.
  if (ground) return Later::MeshGround;
  if (shapes[pair.a].sdf || shapes[pair.b].sdf) return Later::Grid;
  if (compound) return Later::Compound;
  const double margin = settings_.contactMargin + table_->reach[pair.a] + table_->reach[pair.b];
  if (a.shape().isRound() || b.shape().isRound()) {
    const ContactManifold m = collideRoundPair(posed(a), posed(b), margin);
    if (settings_.logQueries) log_.record(summarize(QueryKind::Round, pair.a, pair.b, m, 0.0, time));
    out = {Contact::Kind::BodyBody, pair.a, pair.b, 0, m};
    return Later::Nothing;
  }
  const bool recyclable = recycleTolerance_ > 0.0;
  const RecyclePose poseA = poseOf(a, pair.a), poseB = poseOf(b, pair.b);
  if (recyclable) {
    if (auto m = recycled(Contact::Kind::BodyBody, pair.a, pair.b, poseA, poseB, frame)) {
      out = {Contact::Kind::BodyBody, pair.a, pair.b, 0, *m};
      return Later::Nothing;
    }
  }
  std::optional<OrientedBox> boxA, boxB;
  if (a.shape().type == ShapeType::Box && b.shape().type == ShapeType::Box) {
    boxA = OrientedBox{a.position(), a.rotation(), a.shape().halfExtents};
    boxB = OrientedBox{b.position(), b.rotation(), b.shape().halfExtents};
  }
  ConvexContact c;
  if (boxA) {
    c = collideConvex(a.worldVertices(), b.worldVertices(), margin, &*boxA, &*boxB);
  } else {
    // A hull's faces let a face meet the other body where EPA's axis is two edges' (collideHulls).
    const PosedHullSupport hullA(posed(a)), hullB(posed(b));
    const PointSetSupport pointsA(a.worldVertices()), pointsB(b.worldVertices());
    c = collideHulls(climbs(a) ? static_cast<const SupportMap&>(hullA) : pointsA, a.worldVertices(), facesOf(a),
                     climbs(b) ? static_cast<const SupportMap&>(hullB) : pointsB, b.worldVertices(), facesOf(b), margin);
  }
  if (settings_.logQueries) {
    log_.record(summarize(c.usedBoxSat ? QueryKind::BoxBox : QueryKind::ConvexConvex, pair.a, pair.b, c.manifold, c.distance, time));
  }
  out = {Contact::Kind::BodyBody, pair.a, pair.b, 0, c.manifold};
  if (recyclable && c.manifold.count > 0) frame = recycleFrame(keptKey(Contact::Kind::BodyBody, pair.a, pair.b), c.manifold, poseA, poseB);
  return Later::Nothing;
}

void CollisionPipeline::narrowPhase(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes, double time) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const std::vector<BodySolid>& shapes = table_->solids;
  keepSleeping();
  contacts_.clear();
  reportedStale_ = true;
  recycleTolerance_ = recycleDistance(settings_);
  if (!ignoredSorted_) {
    std::sort(ignored_.begin(), ignored_.end());
    ignoredSorted_ = true;
  }
  // The query log is one ring buffer: a logged step collides on the calling thread alone.
  const int threads = settings_.logQueries ? 1 : settings_.threads;
  // RigidBody::worldVertices() fills its body's cache on first use: filled here, one body per
  // item, so that the pairs below, which share bodies across threads, only read it.
  const auto fill = [&](std::size_t i) {
    if (!bodies[i].shape().isRound() && !bodies[i].isCompound()) bodies[i].worldVertices();
  };
  parallelFor(awake.size(), threads, [&](std::size_t k) { fill(awake[k]); });
  const std::vector<ProxyPair>& pairs = broad_->pairs();
  for (const ProxyPair& p : pairs) {  // and the sleeping or static partners, on this thread
    fill(bodyOfProxy_[p.a]);
    fill(bodyOfProxy_[p.b]);
  }
  pairSlots_.resize(pairs.size());
  pairFrames_.resize(pairs.size());
  later_.assign(pairs.size(), Later::Nothing);
  parallelFor(pairs.size(), threads, [&](std::size_t k) {
    pairFrames_[k].count = 0;
    later_[k] = collidePair(pairs[k], time, pairSlots_[k], pairFrames_[k]);
  });
  collideCompounds(pairs, threads);
  // A pair of compounds gives a contact per pair of children (up to 128^2): the contacts are
  // bounded with the pairs, before the list grows past what a step may hold.
  const auto admit = [&](std::size_t more) {
    if (contacts_.size() + more <= kMaxStepContacts) return;
    contacts_.clear();
    throw StepLimitError("the bodies touch in more than " + std::to_string(kMaxStepContacts) +
                         " contacts, the most a step holds (kMaxStepContacts): compound bodies are piled into one "
                         "place; expected them spread out");
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    admit(later_[k] == Later::Compound || later_[k] == Later::MeshGround ? compoundSlots_[k].size() : later_[k] == Later::Nothing);
    if (later_[k] == Later::Nothing) {
      if (pairSlots_[k].manifold.count > 0) contacts_.push_back(pairSlots_[k]);
      continue;
    }
    if (later_[k] == Later::Compound || later_[k] == Later::MeshGround) {
      contacts_.insert(contacts_.end(), compoundSlots_[k].begin(), compoundSlots_[k].end());
      continue;
    }
    const ProxyPair pair = bodiesOf(pairs[k]);
    const double margin = settings_.contactMargin + table_->reach[pair.a] + table_->reach[pair.b];
    const BodySolid& sa = shapes[pair.a];
    const BodySolid& sb = shapes[pair.b];
    const bool triangles = settings_.meshContact == Settings::MeshContact::Triangles && sa.triangles && sb.triangles;
    const std::vector<ContactManifold> manifolds =
        triangles ? collideMeshes(posedMesh(bodies[pair.a], sa), posedMesh(bodies[pair.b], sb))
                  : collideSdf(bodies[pair.a], sa, bodies[pair.b], sb, margin);
    admit(manifolds.size());
    for (std::size_t m = 0; m < manifolds.size(); ++m) {
      if (settings_.logQueries) {
        log_.record(summarize(triangles ? QueryKind::TriangleTriangle : QueryKind::Sdf, pair.a, pair.b, manifolds[m], 0.0, time));
      }
      contacts_.push_back({Contact::Kind::BodyBody, pair.a, pair.b, static_cast<std::uint8_t>(m), manifolds[m]});
    }
  }
  // Planes against the awake bodies (a sleeping body keeps its plane contacts with its island's).
  const std::size_t n = awake.size();
  planeSlots_.resize(planes.size() * n);
  planeFrames_.resize(planes.size() * n);
  const CollisionFilter planeFilter;  // planes are in the default category and accept every one
  compoundPlaneSlots_.resize(planes.size() * n);
  parallelFor(planes.size() * n, threads, [&](std::size_t k) {
    const std::size_t p = k / n, i = awake[k % n];
    Contact& out = planeSlots_[k];
    out.manifold.count = 0;
    planeFrames_[k].count = 0;
    if (!bodies[i].isDynamic()) return;
    const bool compound = bodies[i].isCompound();
    if (compound) compoundPlaneSlots_[k].clear();
    if (!aabbNearPlane(table_->boxes[i], planes[p], 0.0)) return;
    const double margin = settings_.contactMargin + table_->reach[i];
    if (compound) {
      collidePlaneCompound(planes[p], p, bodies[i], i, margin, table_->reach[i] + kPlaneSupportSlack, compoundPlaneSlots_[k]);
      return;
    }
    if (!shouldCollide(planeFilter, bodies[i].filter())) return;
    const bool round = bodies[i].shape().isRound();
    const bool recyclable = !round && !shapes[i].implicit && recycleTolerance_ > 0.0;
    const RecyclePose planePose{}, bodyPose = poseOf(bodies[i], i);
    if (recyclable) {
      if (auto m = recycled(Contact::Kind::PlaneBody, p, i, planePose, bodyPose, planeFrames_[k])) {
        out = {Contact::Kind::PlaneBody, p, i, 0, *m};
        return;
      }
    }
    // An implicit body meets a plane with its samples on the exact surface, whose corners are
    // sharp; its display mesh's are bevelled.
    const ContactManifold m =
        round ? collidePlaneShape(planes[p], posed(bodies[i]), margin)
              : collidePlaneConvex(planes[p], shapes[i].implicit ? implicitPlaneCandidates(bodies[i], shapes[i], planes[p]) : bodies[i].worldVertices(),
                                   margin, table_->reach[i] + kPlaneSupportSlack);
    if (settings_.logQueries) {
      log_.record(summarize(round ? QueryKind::PlaneRound : QueryKind::PlaneConvex, static_cast<std::uint32_t>(p),
                            static_cast<std::uint32_t>(i), m, 0.0, time));
    }
    out = {Contact::Kind::PlaneBody, p, i, 0, m};
    if (recyclable && m.count > 0) planeFrames_[k] = recycleFrame(keptKey(Contact::Kind::PlaneBody, p, i), m, planePose, bodyPose);
  });
  for (std::size_t k = 0; k < planeSlots_.size(); ++k) {
    const RigidBody& body = bodies[awake[k % n]];
    admit(1 + (body.isCompound() ? compoundPlaneSlots_[k].size() : 0));
    if (planeSlots_[k].manifold.count > 0) contacts_.push_back(planeSlots_[k]);
    if (body.isCompound()) {
      contacts_.insert(contacts_.end(), compoundPlaneSlots_[k].begin(), compoundPlaneSlots_[k].end());
    }
  }
  keepFrames();
}

}  // namespace rbsim
