#include "collision/narrowphase/shape_pairs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "collision/narrowphase/convex_convex.h"
#include "collision/narrowphase/convex_plane.h"
#include "collision/narrowphase/manifold_reduction.h"
#include "geometry/distance.h"

namespace rbsim {

namespace {

// Two capsule axes closer to parallel than this sine touch along a stretch (two points), not at
// one, as two boxes' parallel edges do (convex_convex.cpp's kParallelFeatureSine).
constexpr double kParallelAxisSine = 1e-3;  // [1]
// A clipped stretch shorter than this is one point [m].
constexpr double kMinStretch = 1e-9;  // [m]

// The core a round shape is grown from, in world frame: a sphere's centre, a capsule's segment's
// two ends, a rounded box's eight core corners. On the stack: round shapes collide with each
// other and the ground every step.
struct Core {
  std::array<Vec3, 8> points;
  std::size_t count = 1;
  std::size_t size() const { return count; }
  const Vec3& operator[](std::size_t i) const { return points[i]; }
  const Vec3& front() const { return points[0]; }
  const Vec3& back() const { return points[count - 1]; }
  const Vec3* begin() const { return points.data(); }
  const Vec3* end() const { return points.data() + count; }
};

Core coreOf(const PosedShape& s) {
  Core core;
  if (s.shape->type == ShapeType::Sphere) {
    core.points[0] = s.position;
    return core;
  }
  if (s.shape->type == ShapeType::RoundedBox) {
    const Vec3& h = s.shape->halfExtents;
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
      core.points[static_cast<std::size_t>(i)] = s.rotation * corner + s.position;
    }
    core.count = 8;
    return core;
  }
  const auto [lo, hi] = s.shape->segment();
  core.points[0] = s.rotation * lo + s.position;
  core.points[1] = s.rotation * hi + s.position;
  core.count = 2;
  return core;
}

// Two round shapes of which one has a box core: GJK / EPA and the feature manifold on the cores
// (the face-to-face patch of two rounded boxes resting on each other), each point's depth grown
// by both radii and moved out to midway between the surfaces.
ContactManifold roundBoxCores(const PosedShape& a, const PosedShape& b, const Core& ca, const Core& cb, double margin) {
  const double ra = a.shape->radius, rb = b.shape->radius;
  const std::vector<Vec3> coreA(ca.begin(), ca.end()), coreB(cb.begin(), cb.end());
  const ConvexContact c = collideConvex(coreA, coreB, margin + ra + rb);
  ContactManifold m;
  m.normal = c.manifold.normal;
  const Vec3 shift = 0.5 * (ra - rb) * m.normal;  // A's surface is ra beyond its core, B's rb before its own
  for (int i = 0; i < c.manifold.count; ++i) {
    const ContactPoint& p = c.manifold.points[i];
    if (p.depth + ra + rb >= -margin) m.add(p.position + shift, p.depth + ra + rb);
  }
  return m;
}

// Two round shapes: the closest points of their cores, pushed apart along n by the radii.
ContactManifold roundRound(const PosedShape& a, const PosedShape& b, double margin) {
  const Core ca = coreOf(a), cb = coreOf(b);
  if (ca.size() > 2 || cb.size() > 2) return roundBoxCores(a, b, ca, cb, margin);
  const double ra = a.shape->radius, rb = b.shape->radius;
  Vec3 pa = ca[0], pb = cb[0];
  if (ca.size() == 2 || cb.size() == 2) {
    const SegmentSegmentResult s = closestPointsSegmentSegment(ca.front(), ca.back(), cb.front(), cb.back());
    pa = s.closest1;
    pb = s.closest2;
  }
  ContactManifold m;
  const Vec3 d = pb - pa;
  const double distance = d.norm();
  if (ra + rb - distance < -margin) return m;
  // Concentric cores have no direction between them: A's up axis is as good as any and unit.
  m.normal = distance > 0.0 ? Vec3(d / distance) : Vec3(a.rotation.col(1));
  const auto emit = [&](const Vec3& onA, const Vec3& onB) {
    const double depth = ra + rb - (onB - onA).dot(m.normal);
    if (depth >= -margin) m.add(0.5 * ((onA + ra * m.normal) + (onB - rb * m.normal)), depth);
  };
  const bool bothCapsules = ca.size() == 2 && cb.size() == 2;
  const Vec3 ua = ca.back() - ca.front(), ub = cb.back() - cb.front();
  if (bothCapsules && ua.cross(ub).norm() <= kParallelAxisSine * ua.norm() * ub.norm()) {
    // Parallel capsules: B's segment within A's slab, each end of that stretch a point (Box2D v3's
    // b2CollideCapsules keeps two points for the same reason: a capsule lying on another rests).
    const Vec3 e = ua.normalized();
    const double lo = e.dot(ca.front()), hi = e.dot(ca.back());
    const double t0 = e.dot(cb.front()), t1 = e.dot(cb.back());
    const double from = std::max(lo, std::min(t0, t1)), to = std::min(hi, std::max(t0, t1));
    if (to - from > kMinStretch) {
      for (const double t : {from, to}) {
        const Vec3 onB = cb.front() + ub * ((t - t0) / (t1 - t0));
        emit(closestPointOnSegment(onB, ca.front(), ca.back()).closest, onB);
      }
      return m;
    }
  }
  emit(pa, pb);
  return m;
}

// A round shape against a box or hull: GJK / EPA and the feature manifold on the core, with each
// point's depth grown by the radius and moved out to midway between the surfaces.
ContactManifold roundConvex(const PosedShape& round, const PosedShape& convex, bool roundIsA, double margin) {
  const double r = round.shape->radius;
  const Core roundCore = coreOf(round);
  const std::vector<Vec3> core(roundCore.begin(), roundCore.end()), hull = worldHullVertices(convex);
  const ConvexContact c = roundIsA ? collideConvex(core, hull, margin + r) : collideConvex(hull, core, margin + r);
  ContactManifold m;
  m.normal = c.manifold.normal;
  // The round surface is r beyond its core along the normal, towards the other body.
  const Vec3 shift = (roundIsA ? 0.5 * r : -0.5 * r) * m.normal;
  for (int i = 0; i < c.manifold.count; ++i) {
    const ContactPoint& p = c.manifold.points[i];
    if (p.depth + r >= -margin) m.add(p.position + shift, p.depth + r);
  }
  return m;
}

}  // namespace

std::vector<Vec3> worldHullVertices(const PosedShape& body) {
  std::vector<Vec3> out;
  if (body.shape->type == ShapeType::Box) {
    const Vec3& h = body.shape->halfExtents;
    out.reserve(8);
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
      out.push_back(body.rotation * corner + body.position);
    }
    return out;
  }
  if (body.shape->isRound()) {
    const Core core = coreOf(body);
    return {core.begin(), core.end()};
  }
  out.reserve(body.shape->hull->vertices.size());
  for (const Vec3& p : body.shape->hull->vertices) out.push_back(body.rotation * p + body.position);
  return out;
}

ContactManifold collideRoundPair(const PosedShape& a, const PosedShape& b, double margin) {
  const bool roundA = a.shape->isRound(), roundB = b.shape->isRound();
  if (roundA && roundB) return roundRound(a, b, margin);
  return roundA ? roundConvex(a, b, true, margin) : roundConvex(b, a, false, margin);
}

ContactManifold collidePlaneShape(const Plane& plane, const PosedShape& b, double margin) {
  if (!b.shape->isRound()) return collidePlaneConvex(plane, worldHullVertices(b), margin);
  const double r = b.shape->radius;
  std::array<ContactPoint, std::tuple_size<decltype(Core::points)>::value> candidates;
  std::size_t count = 0;
  for (const Vec3& c : coreOf(b)) {
    // The core point's lowest surface point c - r n, and its projection c - s n onto the plane.
    const double s = plane.signedDistance(c);
    if (r - s >= -margin) candidates[count++] = {c - plane.normal * (0.5 * (s + r)), r - s};
  }
  // A rounded box's core may put more than a manifold's worth of corners within the margin (all
  // eight when its core is thin). A corner above another, along a core edge steeper than 45
  // degrees to the plane (rising more than it moves sideways), rests on nothing the lower one
  // does not: it goes. Of the rest the manifold keeps the deepest and widest four, not the first.
  if (count > static_cast<std::size_t>(kMaxManifoldPoints)) {
    std::array<bool, std::tuple_size<decltype(Core::points)>::value> above{};
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t j = 0; j < count && !above[i]; ++j) {
        const Vec3 offset = candidates[i].position - candidates[j].position;
        const double sideways = (offset - plane.normal * offset.dot(plane.normal)).norm();
        above[i] = candidates[j].depth - candidates[i].depth > sideways;
      }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (!above[i]) candidates[kept++] = candidates[i];
    }
    count = kept;
    if (count > static_cast<std::size_t>(kMaxManifoldPoints)) return reduceContacts(candidates.data(), count, plane.normal);
  }
  ContactManifold m;
  m.normal = plane.normal;
  for (std::size_t i = 0; i < count; ++i) m.add(candidates[i].position, candidates[i].depth);
  return m;
}

}  // namespace rbsim
