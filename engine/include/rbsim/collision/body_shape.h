#pragma once
// A body's solid for point queries, in its body frame: how deep a point is and which way is out.
// Particles, soft-body nodes and the surface samples of other bodies ask it (seed 000 "Rigid Body
// Modeling": "check the surface of one body against the interior volume of another").
#include <memory>
#include <optional>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A body's solid as the intersection of its face planes' inner half-spaces, in body frame: exact
// for convex meshes (boxes), the convex core of a concave one.
struct ConvexShape {
  std::vector<Vec3> normals;    // unit, outward
  std::vector<double> offsets;  // n . p = offset on the face [m]
  double boundingRadius = 0.0;  // every vertex within it of the body origin [m]
};
ConvexShape convexShapeOf(const Mesh& mesh);

// The face of the shape a body-frame point is least deep behind, and its signed distance to that
// face's plane: the signed distance to the convex set when the point is inside (< 0), a lower
// bound of it outside. Empty shapes give face 0 at -infinity.
struct FaceDistance {
  std::size_t face = 0;
  double distance = 0.0;  // [m]
};
FaceDistance nearestFace(const ConvexShape& shape, const Vec3& local);

// What the World keeps per body for point queries: the face planes, and for a body of any shape
// (a bowl, a torus) its signed distance grid and the surface points it tests against others.
struct BodyShape {
  ConvexShape convex;                                // face planes; boundingRadius bounds the body
  std::shared_ptr<const SignedDistanceGrid> sdf;     // null: the face planes are the solid
  std::shared_ptr<const std::vector<Vec3>> samples;  // body frame; null: the mesh's vertices
  std::optional<Shape> round;                        // set for a sphere or capsule: its exact surface
};
BodyShape bodyShapeOf(const BodyDef& def);

// Where a body-frame point is: its signed distance to the surface (< 0 inside; exact inside, and
// outside a lower bound, enough to tell contact) and the outward unit normal there, body frame.
// Callers cull points outside the bounding sphere (convex.boundingRadius) first, before rotating
// them into the body frame, so the query does not test it again.
struct SurfaceQuery {
  double distance = 0.0;        // [m]
  Vec3 normal = Vec3::UnitY();  // unit, body frame
};
SurfaceQuery querySurface(const BodyShape& shape, const Vec3& local);

}  // namespace rbsim
