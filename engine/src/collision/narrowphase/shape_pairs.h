#pragma once
// The narrow phase on shapes (shapes/shape.h): the analytic tests where they are cheap, as
// Box2D v3's manifold.c and Jolt's CollideSphereVsSphere / CollideCapsuleVsCapsule do, and GJK /
// EPA with a clipped feature manifold otherwise (convex_convex.h).
//
// A sphere is a point core (its centre) grown by its radius, a capsule a segment core grown by
// its radius (Ericson 4.5, "sphere-swept volumes"): a pair with a round shape is a pair of cores
// whose contact is pushed out by the radii, so a ball touches the ground at exactly one point at
// exactly its radius, however it has turned.
#include <vector>

#include "rbsim/collision/contact.h"
#include "collision/narrowphase/gjk.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// A shape where its body is: rotation R and centre of mass x.
struct PosedShape {
  const Shape* shape = nullptr;
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();  // [m]
};

// A hull's support mapping in world frame, R support(R^T d) + x, climbing its vertex graph from
// where the last query ended (shapes/shape.h): GJK's successive directions change little, so
// each climb is a few steps where a scan visits every vertex.
class PosedHullSupport final : public SupportMap {
 public:
  explicit PosedHullSupport(const PosedShape& body) : body_(body) {}
  Vec3 support(const Vec3& d) const override {
    return body_.rotation * body_.shape->support(body_.rotation.transpose() * d, &hint_) + body_.position;
  }
  Vec3 anyPoint() const override { return body_.rotation * body_.shape->hull->vertices[0] + body_.position; }

 private:
  PosedShape body_;
  mutable unsigned hint_ = 0;
};

// World-frame vertices of a box's corners or a hull's vertices (what GJK runs on).
std::vector<Vec3> worldHullVertices(const PosedShape& body);

// Contacts of two posed shapes, the normal from A to B, points within `margin` [m] of touching
// included as speculative (depth < 0). For pairs of boxes use collideBoxes (box_box.h), for pairs
// of hulls collideConvex; this handles every pair with a sphere or a capsule in it.
ContactManifold collideRoundPair(const PosedShape& a, const PosedShape& b, double margin);

// A posed shape against a static plane (the plane is A, as collidePlaneConvex): a sphere gives
// one point, a capsule one per cap, a box its corners, a hull its vertices.
ContactManifold collidePlaneShape(const Plane& plane, const PosedShape& b, double margin);

}  // namespace rbsim
