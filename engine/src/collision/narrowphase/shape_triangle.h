#pragma once
// One dynamic shape against one triangle of a static mesh (a terrain, a level): the triangle is a
// convex set of three vertices, so the pair is GJK / EPA with the clipped feature manifold
// (convex_convex.h), on the shape's core grown by its radius for round shapes (Ericson 4.5, as
// shape_pairs.h), and for a sphere the closest point on the triangle (Ericson 5.1.5).
//
// Then the internal-edge fix (Jolt's InternalEdgeRemovingCollector, Bullet's
// btAdjustInternalEdgeContacts, Box2D v3's smooth chain segments): a normal that is not the
// triangle's face normal came from one of its edges or vertices; when none of the touched
// features is an active edge (geometry/triangle_edges.h), the contact is an artefact of the
// triangulation, and it is taken again along the face normal. A box sliding across two coplanar
// triangles otherwise meets the second one's edge side-on and stops.
#include <array>
#include <cstdint>
#include <vector>

#include "collision/narrowphase/shape_pairs.h"
#include "geometry/triangle_edges.h"
#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A touched point of the triangle this close [m] to an edge's line is on that edge.
inline constexpr double kTriangleFeatureTolerance = 1e-3;

struct WorldTriangle {
  std::array<Vec3, 3> vertices;    // world frame [m], counter-clockwise seen from the front
  Vec3 normal = Vec3::UnitY();     // unit, by the winding: the side bodies rest on
  std::uint8_t activeEdges = kAllEdgesActive;  // bit k: edge k (vertex k to k + 1) is active
};

// What GJK runs on for a shape, filled once per shape and reused for every triangle it meets:
// a round shape's core (its centre, its segment's ends, its core box's corners), a box's corners
// or a hull's vertices, world frame. `radius`: what the core is grown by [m] (0: polyhedral).
struct ShapePoints {
  std::vector<Vec3> points;
  double radius = 0.0;
};
void shapePointsOf(const PosedShape& shape, ShapePoints& out);

// The contact of `shape` (its points as shapePointsOf gave) against `triangle`, the normal from
// the triangle to the shape, points within `margin` [m] of touching included (depth < 0), with
// the internal-edge fix applied. count 0: apart.
ContactManifold collideShapeTriangle(const PosedShape& shape, const ShapePoints& points, const WorldTriangle& triangle,
                                     double margin);

// The internal-edge fix alone, on a manifold of `triangle` (A) and a shape (B) grown by `radius`
// [m] whose centre is `centre`: exposed for tests that show what it changes.
void removeInternalEdgeNormal(const WorldTriangle& triangle, const Vec3& centre, double radius, double margin,
                              ContactManifold& m);

}  // namespace rbsim
