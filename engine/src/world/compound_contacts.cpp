#include "world/compound_contacts.h"

#include <algorithm>

#include "collision/narrowphase/box_box.h"
#include "collision/narrowphase/convex_convex.h"
#include "collision/narrowphase/convex_plane.h"
#include "collision/narrowphase/shape_pairs.h"
#include "rbsim/shapes/collision_filter.h"

namespace rbsim {

namespace {

// A child where it is in the world, with what it collides with.
struct PosedChild {
  PosedShape posed;
  const CollisionFilter* filter = nullptr;
  std::size_t index = 0;
  Aabb box;
};

void posedChildren(const RigidBody& body, double margin, std::vector<PosedChild>& out) {
  out.clear();
  const Mat3& R = body.rotation();
  if (!body.isCompound()) {
    const auto [lo, hi] = body.shape().worldBounds(R, body.position());
    out.push_back({{&body.shape(), R, body.position()}, &body.filter(), 0, Aabb{lo, hi}.inflated(margin)});
    return;
  }
  const std::vector<ChildShape>& children = body.children();
  for (std::size_t c = 0; c < children.size(); ++c) {
    const Mat3 rotation = R * children[c].orientation.toRotationMatrix();
    const Vec3 position = body.bodyToWorld(children[c].position);
    const auto [lo, hi] = children[c].shape.worldBounds(rotation, position);
    out.push_back({{&children[c].shape, rotation, position}, &children[c].filter, c, Aabb{lo, hi}.inflated(margin)});
  }
}

ContactManifold collideShapes(const PosedShape& a, const PosedShape& b, double margin) {
  if (a.shape->isRound() || b.shape->isRound()) return collideRoundPair(a, b, margin);
  const std::vector<Vec3> va = worldHullVertices(a), vb = worldHullVertices(b);
  if (a.shape->type == ShapeType::Box && b.shape->type == ShapeType::Box) {
    const OrientedBox boxA{a.position, a.rotation, a.shape->halfExtents};
    const OrientedBox boxB{b.position, b.rotation, b.shape->halfExtents};
    return collideConvex(va, vb, margin, &boxA, &boxB).manifold;
  }
  return collideConvex(va, vb, margin).manifold;
}

}  // namespace

Aabb compoundBounds(const RigidBody& body) {
  Aabb box;
  const Mat3& R = body.rotation();
  for (const ChildShape& child : body.children()) {
    const auto [lo, hi] = child.shape.worldBounds(R * child.orientation.toRotationMatrix(), body.bodyToWorld(child.position));
    box.grow(lo);
    box.grow(hi);
  }
  return box;
}

double compoundRadius(const RigidBody& body) {
  double radius = 0.0;
  for (const ChildShape& child : body.children()) {
    radius = std::max(radius, child.position.norm() + child.shape.boundingRadius());
  }
  return radius;
}

void collideCompoundPair(const RigidBody& a, std::size_t ia, const RigidBody& b, std::size_t ib, double margin,
                         std::vector<Contact>& out) {
  // Per thread: the pair tests run on any thread of the narrow phase.
  thread_local std::vector<PosedChild> childrenA, childrenB;
  posedChildren(a, margin, childrenA);
  posedChildren(b, 0.0, childrenB);
  for (const PosedChild& ca : childrenA) {
    for (const PosedChild& cb : childrenB) {
      if (!ca.box.overlaps(cb.box) || !shouldCollide(*ca.filter, *cb.filter)) continue;
      const ContactManifold m = collideShapes(ca.posed, cb.posed, margin);
      if (m.count == 0) continue;
      out.push_back({Contact::Kind::BodyBody, ia, ib, compoundPart(ca.index, cb.index), m,
                     static_cast<std::uint16_t>(ca.index), static_cast<std::uint16_t>(cb.index)});
    }
  }
}

void collidePlaneCompound(const Plane& plane, std::size_t p, const RigidBody& body, std::size_t i, double margin,
                          double supportSlab, std::vector<Contact>& out) {
  thread_local std::vector<PosedChild> children;
  posedChildren(body, margin, children);
  const CollisionFilter planeFilter;  // planes are in the default category and accept every one
  for (const PosedChild& child : children) {
    if (!shouldCollide(planeFilter, *child.filter)) continue;
    const ContactManifold m = child.posed.shape->isRound()
                                  ? collidePlaneShape(plane, child.posed, margin)
                                  : collidePlaneConvex(plane, worldHullVertices(child.posed), margin, supportSlab);
    if (m.count == 0) continue;
    out.push_back({Contact::Kind::PlaneBody, p, i, compoundPart(0, child.index), m, 0, static_cast<std::uint16_t>(child.index)});
  }
}

}  // namespace rbsim
