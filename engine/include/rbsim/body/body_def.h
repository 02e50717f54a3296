#pragma once
// Plain definition a RigidBody is created from (as Box2D's b2BodyDef): everything is explicit,
// already validated and in SI units. mass/mass_model.h builds the mass part from a shape.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rbsim/body/child_shape.h"
#include "rbsim/body/material.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

struct FracturePattern;     // fracture/fracture.h
class SignedDistanceGrid;   // geometry/signed_distance_grid.h
struct ImplicitSolid;       // shapes/implicit_shape.h (private)
class TriangleBvh;          // geometry/triangle_bvh.h (private)

// Where the body frame sits in the coordinates of the file the body came from (seed 000's
// diagonalisation, mass/mass_model.h): p_file = axes p_body + centre.
struct FileFrame {
  Mat3 axes = Mat3::Identity();  // the principal axes, columns in file coordinates (a rotation)
  Vec3 centre = Vec3::Zero();    // the centre of mass in file coordinates [m]
  std::shared_ptr<const Mesh> mesh;  // the file's vertices as given; null: axes p_body + centre
};

struct BodyDef {
  std::string name = "body";
  std::shared_ptr<const Mesh> mesh;        // body space: the origin is the centre of mass
  FileFrame fileFrame;                     // the body frame in the file's coordinates
  double mass = 1.0;                       // [kg], > 0
  Mat3 inertiaBody = Mat3::Identity();     // [kg m^2] about the centre of mass, body axes
  Vec3 position = Vec3::Zero();            // x: world position of the centre of mass [m]
  Quat orientation = Quat::Identity();     // q: body-to-world rotation (unit)
  Vec3 velocity = Vec3::Zero();            // v of the centre of mass [m/s]
  Vec3 angularVelocity = Vec3::Zero();     // omega, world frame [rad/s]
  Material material;                       // restitution and friction (body/material.h)
  // A static body never moves: it is not integrated, forces do not act on it, and it behaves as
  // if its mass were infinite. Its mass and inertia are kept for display only.
  bool isStatic = false;
  // A kinematic body (seed 000's "infinite mass kinematic objects", K = 0) moves with its velocity
  // and angular velocity, which only the program changes (setVelocity, a pose event): gravity,
  // forces and contacts do not act on it, and it pushes and carries dynamic bodies as if its mass
  // were infinite. Not both static and kinematic.
  bool isKinematic = false;
  // The collision shape (shapes/shape.h), in the body frame of `mesh`. Unset: the mesh decides,
  // as shapeOfMesh does (a box's eight corners make a box, a body with a grid is a mesh, any
  // other mesh its convex hull), so a body built in C++ collides as the same body read from JSON.
  std::optional<Shape> shape;
  // What the shape collides with (shapes/collision_filter.h); a compound's children have their own.
  CollisionFilter filter;
  // A compound body: its shapes in the body frame (body/compound_body.h builds one, with the mass
  // properties summed about the centre of mass). Empty: the body is its one `shape`. A compound
  // body's `mesh` is its children's display meshes together, and `shape` their convex hull, which
  // only what has no use for the children reads (the continuous stage leaves compounds alone).
  std::vector<ChildShape> children;
  // Set for a body that breaks into these pieces when a contact impulse exceeds the pattern's
  // threshold (seed 000 "Fracture"; World stage BreakBodies).
  std::shared_ptr<const FracturePattern> fracture;
  // Set for a body of any shape, convex or not (seed 000 "Rigid Body Modeling"): its interior as
  // a signed distance grid in body frame, and the surface points tested against other bodies'
  // grids (null: the vertices). Without a grid, contacts treat the body as convex.
  std::shared_ptr<const SignedDistanceGrid> sdf;
  std::shared_ptr<const std::vector<Vec3>> surfaceSamples;
  // Set for a body made from an implicit function or a CSG tree: its exact solid. The grid then
  // only finds candidates, and depths and normals against the body are the function's.
  std::shared_ptr<const ImplicitSolid> implicit;
  // Set for a non-convex mesh body with a grid: the hierarchy over its body-frame triangles, for
  // contact by crossing triangles (Settings::meshContact).
  std::shared_ptr<const TriangleBvh> triangles;
};

}  // namespace rbsim
