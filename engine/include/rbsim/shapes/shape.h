#pragma once
// A body's collision shape, one of a small closed set (as Jolt's Physics/Collision/Shape/ and
// Box2D's b2ShapeType): sphere, capsule, box, rounded box, convex hull, and a non-convex mesh
// whose solid is a signed distance grid. The sixth, the infinite static plane, is the World's (World::addPlane,
// shapes/plane.h): it is never a body. Everything here is in the body frame, whose
// origin is the centre of mass; the narrow phase picks the pair test from the two types
// (collision/narrowphase/shape_pairs.h).
//
// The display mesh (RigidBody::mesh, seed 004's vertex list) is separate: a sphere is drawn as a
// 48 x 24 polyhedron inscribed in it, but collides and weighs as the exact sphere.
#include <memory>
#include <utility>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/face_planes.h"

namespace rbsim {

enum class ShapeType { Sphere, Capsule, Box, RoundedBox, ConvexHull, Mesh };
const char* shapeTypeName(ShapeType type);

// A convex polyhedron's vertices with, per vertex, its neighbours along the mesh's edges, for
// the hill-climbing support search (van den Bergen 2003, section 4.3.4; Bullet's
// btConvexHullShape scans, Jolt's ConvexHullShape keeps the same adjacency). A vertex whose
// neighbours are all no further along d is the furthest of the whole hull, since a convex
// polyhedron's vertex graph has no other local maximum.
struct HullAdjacency {
  std::vector<Vec3> vertices;                   // body frame [m]
  std::vector<std::vector<unsigned>> neighbours;  // per vertex, indices into vertices
};
// The vertices of a closed triangle mesh (its hull: callers pass convex ones) and their edges.
// Duplicate vertices (a UV sphere's poles and seam) are merged first, so the graph is connected.
HullAdjacency hullAdjacencyOf(const Mesh& mesh);

// Vertex counts up to this are scanned: a scan of a few dozen points is faster than following
// neighbour lists (measured in bench/narrowphase_bench, BM_HullSupport).
inline constexpr std::size_t kHillClimbMinVertices = 32;

struct Shape {
  ShapeType type = ShapeType::ConvexHull;
  double radius = 0.0;          // sphere, capsule, rounded box [m]
  double halfLength = 0.0;      // capsule: half the distance between its two cap centres, on body y [m]
  Vec3 halfExtents = Vec3::Zero();  // box, rounded box's core [m], along body x, y, z
  // Convex hull and mesh: the vertices that span the hull (for a mesh, of its convex hull, which
  // GJK sees when the other body has no grid), with their adjacency for large hulls.
  std::shared_ptr<const HullAdjacency> hull;
  // Convex hull: its face planes, for exact distances inside and ray casts
  // (collision/shape_queries.h). Null for a mesh, whose hull's faces are not its own.
  std::shared_ptr<const FacePlanes> faces;

  // Each throws std::invalid_argument unless its sizes are positive and finite (a capsule's half
  // length may be 0: a sphere) and the mesh has a vertex.
  static Shape sphere(double radius);
  static Shape capsule(double radius, double halfLength);
  static Shape box(const Vec3& halfExtents);
  // A box with rounded edges and corners: the points within `radius` of a core box of
  // `coreHalfExtents` (the Minkowski sum of the box and a ball, as Jolt's convex radius). Its
  // outer half extents are coreHalfExtents + radius; a core extent may be 0 (a slab, a capsule).
  static Shape roundedBox(const Vec3& coreHalfExtents, double radius);
  static Shape convexHull(const Mesh& mesh);
  static Shape mesh(const Mesh& mesh);  // non-convex: the body also needs a grid (BodyDef::sdf)

  // A core (a point, a segment, a box) grown by `radius`: the narrow phase collides the cores.
  bool isRound() const { return type == ShapeType::Sphere || type == ShapeType::Capsule || type == ShapeType::RoundedBox; }
  // Capsule: its segment's ends in body frame, (0, -h, 0) and (0, h, 0).
  std::pair<Vec3, Vec3> segment() const { return {Vec3(0.0, -halfLength, 0.0), Vec3(0.0, halfLength, 0.0)}; }

  // The point of the shape furthest along d (body frame, d != 0). Hulls of more than
  // kHillClimbMinVertices climb from `hint` (a vertex index, updated: pass the last answer's
  // to start next to it) instead of scanning; others ignore it.
  Vec3 support(const Vec3& d, unsigned* hint = nullptr) const;
  // Largest distance of a point of the shape from the body origin [m].
  double boundingRadius() const;
  // World-space bounding box of the shape at pose (R, x): exact for every type.
  std::pair<Vec3, Vec3> worldBounds(const Mat3& R, const Vec3& x) const;
  // Signed distance of a body-frame point to a round shape's surface (< 0 inside) and the
  // outward unit normal there; only for round shapes.
  std::pair<double, Vec3> roundDistance(const Vec3& local) const;
};

// The shape a mesh stands for when nothing else is said: a box when its vertices are the eight
// corners (+-hx, +-hy, +-hz) (makeBox's, an OBJ cube's), a Mesh when the body has a signed
// distance grid (`hasGrid`), its convex hull otherwise.
Shape shapeOfMesh(const Mesh& mesh, bool hasGrid);

// Closed-form mass properties about the centre (the shape's origin) for a uniform solid of
// `density` [kg/m^3]: sphere I = 2/5 m r^2; capsule = cylinder + two hemispheres shifted by the
// parallel-axis theorem (the hemisphere's centroid is 3r/8 from its flat face); box m/12 (b^2 +
// c^2); rounded box summed over its core, face slabs, edge quarter-cylinders and corner ball
// eighths (shape.cpp). Hulls and meshes use the polyhedral integrals (mass/mass_properties.h).
double roundOrBoxVolume(const Shape& shape);         // [m^3]
Mat3 roundOrBoxInertia(const Shape& shape, double mass);  // [kg m^2], diagonal in body axes

}  // namespace rbsim
