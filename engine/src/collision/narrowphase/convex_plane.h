#pragma once
// A convex vertex set against a static Plane: the vertices below the plane (or within a
// speculative margin above it) are the contact points (seed 004 "Collision detection": contact
// point, normal, depth), reduced to at most 4 (collision/narrowphase/manifold_reduction.h).
//
// Convention: the plane is body A and the vertex set body B, so the manifold's normal (from A to
// B) is the plane's normal, pointing out of the solid half-space towards the body. A point's
// depth is -signedDistance of its vertex; its position is midway between the vertex and the
// vertex's projection onto the plane.
#include <cstddef>
#include <limits>
#include <vector>

#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

// `margin` [m] >= 0: vertices up to this far above the plane are speculative contacts (depth < 0).
// `supportSlab` [m]: only vertices at most this much shallower than the deepest are candidates for
// the manifold; the caller passes how far the body can move in the step (its reach), so the
// corners of a tumbling body coming down stay in. A body at rest on a face of many vertices (a
// mesh from an implicit surface, whose sharp edges are bevelled half a grid cell above the face)
// is then held by its face, not by bevel vertices hanging above the plane whose wider footprint
// reduction by area would prefer.
// Above this many candidates only those on the outline of their projection, and the deepest,
// go on (an implicit body's samples on a face are thousands; a box's corners are 4).
inline constexpr std::size_t kPlaneHullCandidates = 64;
ContactManifold collidePlaneConvex(const Plane& plane, const std::vector<Vec3>& vertices, double margin = 0.0,
                                   double supportSlab = std::numeric_limits<double>::infinity());

}  // namespace rbsim
