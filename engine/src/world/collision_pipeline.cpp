#include "world/collision_pipeline.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

#include "collision/broadphase/brute_force.h"
#include "collision/broadphase/sweep_and_prune.h"
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

std::unique_ptr<BroadPhase> makeBroadPhase(Settings::BroadPhaseMethod method) {
  if (method == Settings::BroadPhaseMethod::BruteForce) return std::make_unique<BruteForce>();
  return std::make_unique<SweepAndPrune>();
}

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

CollisionPipeline::CollisionPipeline(const Settings& settings)
    : settings_(settings), broad_(makeBroadPhase(settings.broadPhase)), log_(settings.queryLogCapacity) {}

CollisionPipeline::CollisionPipeline(const CollisionPipeline& other)
    : settings_(other.settings_),
      broad_(other.broad_->clone()),
      proxies_(other.proxies_),
      bodyOfProxy_(other.bodyOfProxy_),
      radius_(other.radius_),
      thickness_(other.thickness_),
      reach_(other.reach_),
      start_(other.start_),
      fast_(other.fast_),
      hasGrid_(other.hasGrid_),
      meshGround_(other.meshGround_),
      gap_(other.gap_),
      haveStart_(other.haveStart_),
      boxes_(other.boxes_),
      ignored_(other.ignored_),
      ignoredSorted_(other.ignoredSorted_),
      contacts_(other.contacts_),
      previous_(other.previous_),
      asleep_(other.asleep_),
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

bool CollisionPipeline::needsBroadPhase(const std::vector<RigidBody>& bodies, const std::vector<Plane>& planes) const {
  if (bodies.size() < 2 && planes.empty()) return false;
  return std::any_of(bodies.begin(), bodies.end(), [](const RigidBody& b) { return b.awake(); });
}

void CollisionPipeline::rememberStart(const std::vector<RigidBody>& bodies) {
  for (std::size_t i = 0; i < bodies.size(); ++i) start_[i] = bodies[i].state();
  haveStart_ = true;
}

bool CollisionPipeline::isFast(std::size_t body) const { return fast_[body] != 0; }

void CollisionPipeline::continuous(std::vector<RigidBody>& bodies, const std::vector<Plane>& planes,
                                   const std::vector<char>* solved) {
  impacts_.clear();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& body = bodies[i];
    fast_[i] = 0;
    // A kinematic body goes where it is told, through anything: it is never stopped. A body with a
    // grid is swept too, as its convex hull, which holds it: it may stop a little early (at its
    // hull's touch, where the grid's contacts take over), never late. Its partners with grids
    // are not swept against (a ball falling into a bowl would stop at the bowl's hull).
    if (!body.awake() || !haveStart_ || body.isKinematic()) continue;
    // Stopping a body the solver moved would undo its speculative contacts, which already hold
    // it at the surfaces it can reach this step (and hold it still, again, every step after).
    if (solved != nullptr && i < solved->size() && (*solved)[i] != 0) continue;
    const double motion = motionBound(sweptOf(body, start_[i], radius_[i]));
    fast_[i] = motion > settings_.ccdMotionFraction * thickness_[i] ? 1 : 0;
  }
  if (std::none_of(fast_.begin(), fast_.end(), [](char f) { return f != 0; })) {
    haveStart_ = false;
    return;
  }
  // Each body's box over its whole step (last step's box, which covers the start pose, grown by
  // the end pose), computed once: a contact during the step lies inside both bodies' boxes.
  std::vector<Aabb> stepBoxes(bodies.size());
  for (std::size_t j = 0; j < bodies.size(); ++j) {
    stepBoxes[j] = boxes_[j];
    if (bodies[j].awake()) stepBoxes[j].grow(bodyBounds(bodies[j]));
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!isFast(i)) continue;
    const SweptBody swept = sweptOf(bodies[i], start_[i], radius_[i]);
    double first = 1.0;
    for (const Plane& plane : planes) {
      if (const auto s = timeOfImpact(swept, plane)) first = std::min(first, *s);
    }
    Aabb sweep = boundsAt(swept, 0.0);
    sweep.grow(boundsAt(swept, 1.0));
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      if (j == i || hasGrid_[j] || !sweep.overlaps(stepBoxes[j])) continue;
      const SweptBody partner = sweptOf(bodies[j], start_[j], radius_[j]);
      if (const auto s = timeOfImpact(swept, partner)) first = std::min(first, *s);
    }
    if (first < 1.0) {
      impacts_.push_back({i, first, bodies[i].position(), bodies[i].orientation()});
      bodies[i].setState(poseAt(swept, first));  // momenta kept: the response is the solver's
    }
  }
  haveStart_ = false;
}

void CollisionPipeline::broadPhase(const std::vector<RigidBody>& bodies) {
  // Each awake body's box on any thread, then into the broad phase in body order.
  parallelFor(bodies.size(), settings_.threads, [&](std::size_t i) {
    if (!bodies[i].awake()) return;
    Aabb box = bodyBounds(bodies[i]);
    if (isFast(i)) box.grow(boundsAt(sweptOf(bodies[i], start_[i], radius_[i]), 0.0));
    const double dt = settings_.timeStep;
    reach_[i] = dt * (bodies[i].velocity().norm() + bodies[i].angularVelocity().norm() * radius_[i] +
                      dt * settings_.gravity.norm());
    boxes_[i] = box.inflated(settings_.contactMargin + gap_[i] + reach_[i]);
  });
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].awake()) continue;
    // A finite state can still have a box that is not (a vertex R p + x or a reach dt |v|
    // overflows): that is the body diverging, reported as such rather than as a broad-phase fault.
    if (!boxes_[i].min.allFinite() || !boxes_[i].max.allFinite()) {
      std::ostringstream message;
      message << "body '" << bodies[i].name() << "': its bounding box stopped being finite (|x| = "
              << bodies[i].position().stableNorm() << " m, |v| = " << bodies[i].velocity().stableNorm() << " m/s)";
      throw SimulationError(message.str());
    }
    broad_->move(proxies_[i], boxes_[i]);
  }
  broad_->update();
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

CollisionPipeline::Later CollisionPipeline::collidePair(const ProxyPair& proxies, const std::vector<RigidBody>& bodies,
                                                       const std::vector<BodySolid>& shapes, double time, Contact& out,
                                                       RecycleFrame& frame) {
  out.manifold.count = 0;
  // Body indices, the lower first (a destroyed body's index goes to the last body, whose proxy id
  // stays as it was).
  ProxyPair pair{static_cast<ProxyId>(bodyOfProxy_[proxies.a]), static_cast<ProxyId>(bodyOfProxy_[proxies.b])};
  if (pair.a > pair.b) std::swap(pair.a, pair.b);
  if (!ignored_.empty() &&
      std::binary_search(ignored_.begin(), ignored_.end(), (std::uint64_t{pair.a} << 32) | std::uint64_t{pair.b})) {
    return Later::Nothing;
  }
  const RigidBody& a = bodies[pair.a];
  const RigidBody& b = bodies[pair.b];
  // A compound's children are filtered one by one (compound_contacts.h, mesh_ground_contacts.h).
  const bool compound = a.isCompound() || b.isCompound();
  const bool ground = meshGround_[pair.a] || meshGround_[pair.b];
  if (!compound && !ground && !shouldCollide(a.filter(), b.filter())) return Later::Nothing;
  if (!a.awake() && !b.awake()) {
    // Both asleep: the contact they fell asleep with (Box2D keeps a sleeping set's contacts,
    // solver_set.c), so that an island woken this step has its inner contacts in place; without
    // them each body it woke fell a step unsupported, and sleep cost a 4000-box pile time.
    const bool grid = shapes[pair.a].sdf || shapes[pair.b].sdf;  // several manifolds: left out, as before
    if (ground) return Later::MeshGround;
    if (compound) return Later::Compound;
    if (!grid) kept(Contact::Kind::BodyBody, pair.a, pair.b, out);
    return Later::Nothing;
  }
  // Static and kinematic bodies pass through each other: both have infinite mass (seed 000's
  // K = 0), so no impulse could separate them.
  if (!a.isDynamic() && !b.isDynamic()) return Later::Nothing;
  // Before the grid's test: a body with a grid meets a mesh ground as its convex hull.
  if (ground) return Later::MeshGround;
  if (shapes[pair.a].sdf || shapes[pair.b].sdf) return Later::Grid;
  if (compound) return Later::Compound;
  const double margin = settings_.contactMargin + reach_[pair.a] + reach_[pair.b];
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

void CollisionPipeline::narrowPhase(const std::vector<RigidBody>& bodies, const std::vector<BodySolid>& shapes,
                                    const std::vector<Plane>& planes, double time) {
  previous_.swap(contacts_);
  contacts_.clear();
  asleep_.clear();
  recycleTolerance_ = recycleDistance(settings_);
  for (std::size_t i = 0; i < previous_.size(); ++i) {
    const Contact& c = previous_[i];
    const bool plane = c.kind == Contact::Kind::PlaneBody;
    // A pair with a compound or a mesh ground keeps all its contacts, one per part.
    const bool several = bodies[c.b].isCompound() || (!plane && (bodies[c.a].isCompound() || meshGround_[c.a] || meshGround_[c.b]));
    if ((c.part == 0 || several) && !bodies[c.b].awake() && (plane || !bodies[c.a].awake())) {
      asleep_.emplace_back(keptKey(c.kind, c.a, c.b), static_cast<std::uint32_t>(i));
    }
  }
  std::sort(asleep_.begin(), asleep_.end());
  if (!ignoredSorted_) {
    std::sort(ignored_.begin(), ignored_.end());
    ignoredSorted_ = true;
  }
  // The query log is one ring buffer: a logged step collides on the calling thread alone.
  const int threads = settings_.logQueries ? 1 : settings_.threads;
  // RigidBody::worldVertices() fills its body's cache on first use: filled here, one body per
  // item, so that the pairs below, which share bodies across threads, only read it.
  parallelFor(bodies.size(), threads, [&](std::size_t i) {
    if (!bodies[i].shape().isRound() && !bodies[i].isCompound()) bodies[i].worldVertices();
  });
  const std::vector<ProxyPair>& pairs = broad_->pairs();
  pairSlots_.resize(pairs.size());
  pairFrames_.resize(pairs.size());
  later_.assign(pairs.size(), Later::Nothing);
  parallelFor(pairs.size(), threads, [&](std::size_t k) {
    pairFrames_[k].count = 0;
    later_[k] = collidePair(pairs[k], bodies, shapes, time, pairSlots_[k], pairFrames_[k]);
  });
  collideCompounds(pairs, bodies, shapes, threads);
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
    ProxyPair pair{static_cast<ProxyId>(bodyOfProxy_[pairs[k].a]), static_cast<ProxyId>(bodyOfProxy_[pairs[k].b])};
    if (pair.a > pair.b) std::swap(pair.a, pair.b);
    const double margin = settings_.contactMargin + reach_[pair.a] + reach_[pair.b];
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
  const std::size_t n = bodies.size();
  planeSlots_.resize(planes.size() * n);
  planeFrames_.resize(planes.size() * n);
  const CollisionFilter planeFilter;  // planes are in the default category and accept every one
  compoundPlaneSlots_.resize(planes.size() * n);
  parallelFor(planes.size() * n, threads, [&](std::size_t k) {
    const std::size_t p = k / n, i = k % n;
    Contact& out = planeSlots_[k];
    out.manifold.count = 0;
    planeFrames_[k].count = 0;
    if (!bodies[i].isDynamic()) return;
    const bool compound = bodies[i].isCompound();
    if (compound) compoundPlaneSlots_[k].clear();
    if (!bodies[i].awake()) {  // the contact it fell asleep with, as for two sleeping bodies
      if (compound) {
        keptAll(Contact::Kind::PlaneBody, p, i, compoundPlaneSlots_[k]);
      } else {
        kept(Contact::Kind::PlaneBody, p, i, out);
      }
      return;
    }
    if (!aabbNearPlane(boxes_[i], planes[p], 0.0)) return;
    const double margin = settings_.contactMargin + reach_[i];
    if (compound) {
      collidePlaneCompound(planes[p], p, bodies[i], i, margin, reach_[i] + kPlaneSupportSlack, compoundPlaneSlots_[k]);
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
                                   margin, reach_[i] + kPlaneSupportSlack);
    if (settings_.logQueries) {
      log_.record(summarize(round ? QueryKind::PlaneRound : QueryKind::PlaneConvex, static_cast<std::uint32_t>(p),
                            static_cast<std::uint32_t>(i), m, 0.0, time));
    }
    out = {Contact::Kind::PlaneBody, p, i, 0, m};
    if (recyclable && m.count > 0) planeFrames_[k] = recycleFrame(keptKey(Contact::Kind::PlaneBody, p, i), m, planePose, bodyPose);
  });
  for (std::size_t k = 0; k < planeSlots_.size(); ++k) {
    admit(1 + (bodies[k % n].isCompound() ? compoundPlaneSlots_[k].size() : 0));
    if (planeSlots_[k].manifold.count > 0) contacts_.push_back(planeSlots_[k]);
    if (bodies[k % n].isCompound()) {
      contacts_.insert(contacts_.end(), compoundPlaneSlots_[k].begin(), compoundPlaneSlots_[k].end());
    }
  }
  keepFrames();
}

}  // namespace rbsim
