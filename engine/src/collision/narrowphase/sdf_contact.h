#pragma once
// Contacts between bodies of any shape, convex or not, as seed 000 "Collision Detection" says:
// "test all the triangulated surface points of one body against the implicit surface volume of
// the other (and vice versa)". A world point goes into the other body's object space as
// x_o = R^T (x_w - x), its depth is -phi(x_o), and the contact normal is grad phi / |grad phi|,
// rotated back to world. The points of one pair rarely share one normal (a box in a bowl touches
// the floor and the wall), so they are grouped by normal into several manifolds.
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

// Points whose normals lie within this angle of a manifold's first (deepest) point join it; the
// rest start manifolds of their own.
inline constexpr double kSdfManifoldAngle = 0.35;  // [rad], 20 degrees
// At most this many manifolds per pair: a body resting in a bowl's curve needs a few, and the
// solver's cost grows with each.
inline constexpr int kMaxSdfManifolds = 6;

// A contact point of a pair of bodies of any shape, with its own normal.
struct PointContact {
  Vec3 position;  // midway between the surfaces, world [m]
  Vec3 normal;    // unit, world, from A to B
  double depth;   // [m], > 0 overlapping
};
// The points grouped by normal, deepest first: a point joins the group whose normal is nearest if
// within kSdfManifoldAngle, else starts one (at most kMaxSdfManifolds); each group is reduced to
// a manifold (manifold_reduction.h). Sorts `points`.
std::vector<ContactManifold> manifoldsByNormal(std::vector<PointContact>& points);

// The manifolds (normal from A to B, each of at most kMaxManifoldPoints) of the pair: A's surface
// samples (or vertices) within `margin` [m] of B's solid, and B's within it of A's. Empty when
// they are apart by more than the margin.
std::vector<ContactManifold> collideSdf(const RigidBody& a, const BodySolid& shapeA, const RigidBody& b,
                                        const BodySolid& shapeB, double margin);

}  // namespace rbsim
