#pragma once
// One shape of a compound body (a table's top and legs, a drum's staves): where it sits in the
// body frame, what it is made of and what it collides with. Each child collides on its own, with
// its own contact points, normals and material (Box2D v3 and Jolt attach many shapes to one body;
// Jolt's StaticCompoundShape keeps each sub-shape's position and rotation the same way).
#include <memory>

#include "rbsim/body/material.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// A compound body has at most this many children, so that a pair of children names its contact
// in the solver's warm-start key in 14 bits (dynamics/contact_key.h). Box3D's washer drum has 40.
inline constexpr int kMaxCompoundChildren = 128;

struct ChildShape {
  Shape shape;                           // in the child's own frame (a box's centre, a hull's vertices)
  Vec3 position = Vec3::Zero();          // the child frame's origin in the body frame [m]
  Quat orientation = Quat::Identity();   // child frame to body frame (unit)
  Material material;
  CollisionFilter filter;
  std::shared_ptr<const Mesh> mesh;      // its display mesh, child frame (body/shape_body.h)
};

}  // namespace rbsim
