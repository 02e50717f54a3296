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
#include "rbsim/shapes/face_planes.h"

namespace rbsim {

struct ImplicitSolid;  // shapes/implicit_shape.h (private)
class TriangleBvh;     // geometry/triangle_bvh.h (private)

// One child of a compound body for point queries: its pose in the body frame and its solid.
struct ChildSolid {
  Mat3 rotation = Mat3::Identity();  // child frame to body frame
  Vec3 position = Vec3::Zero();      // the child frame's origin, body frame [m]
  FacePlanes convex;                 // a box's or hull's faces
  std::optional<Shape> round;        // set for a round child
};

// What the World keeps per body for point queries: the face planes, and for a body of any shape
// (a bowl, a torus) its signed distance grid and the surface points it tests against others.
struct BodySolid {
  FacePlanes convex;  // face planes (none with an sdf, which answers instead); boundingRadius bounds the body
  std::shared_ptr<const SignedDistanceGrid> sdf;     // null: the face planes are the solid
  std::shared_ptr<const std::vector<Vec3>> samples;  // body frame; null: the mesh's vertices
  std::optional<Shape> round;                        // set for a round shape: its exact surface
  std::shared_ptr<const ImplicitSolid> implicit;     // set for an implicit body: its exact solid
  std::shared_ptr<const TriangleBvh> triangles;      // set for a non-convex mesh body (BodyDef::triangles)
  // Set for a compound body: its children, whose union is the solid (the nearest child answers).
  std::shared_ptr<const std::vector<ChildSolid>> children;
};
BodySolid bodySolidOf(const BodyDef& def);

// Where a body-frame point is: its signed distance to the surface (< 0 inside; exact inside, and
// outside a lower bound, enough to tell contact) and the outward unit normal there, body frame.
// An implicit body answers from its exact function within kExactBandCells cells of its surface
// (as the grid tells), from its grid farther out.
// Callers cull points outside the bounding sphere (convex.boundingRadius) first, before rotating
// them into the body frame, so the query does not test it again.
struct SurfaceQuery {
  double distance = 0.0;        // [m]
  Vec3 normal = Vec3::UnitY();  // unit, body frame
};
inline constexpr double kExactBandCells = 2.0;  // [cells]; the grid's error is under a cell's diagonal
SurfaceQuery querySurface(const BodySolid& shape, const Vec3& local);

}  // namespace rbsim
