#pragma once
// The narrow phase of compound bodies (body/child_shape.h): each child of one body against each
// child of the other (or a plane) whose boxes meet and whose filters accept each other, with the
// pair tests of single shapes (collision/narrowphase/shape_pairs.h). A body of one shape takes
// part as its only child. Each child pair gives its own manifold, named by compoundPart.
#include <cstddef>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/contact.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/shapes/plane.h"

namespace rbsim {

// The bounding box of a compound body's children at the body's pose.
Aabb compoundBounds(const RigidBody& body);
// The farthest point of a compound's children from its centre of mass [m].
double compoundRadius(const RigidBody& body);

// Contacts of bodies a and b (indices ia < ib), one of them compound, appended to `out`.
void collideCompoundPair(const RigidBody& a, std::size_t ia, const RigidBody& b, std::size_t ib, double margin,
                         std::vector<Contact>& out);
// Contacts of plane p and compound body `body` (index i), appended to `out`. `supportSlab` [m]:
// as collidePlaneConvex's.
void collidePlaneCompound(const Plane& plane, std::size_t p, const RigidBody& body, std::size_t i, double margin,
                          double supportSlab, std::vector<Contact>& out);

}  // namespace rbsim
