#pragma once
// A compound body (a table of five boxes, a hammer, a drum of staves) from its parts, each a
// shape where the caller puts it: the exact mass properties of each part, summed about the
// common centre of mass by the parallel-axis theorem (Steiner; as Box2D v3's b2UpdateBodyMassData
// and Jolt's StaticCompoundShape::GetMassProperties), the children posed about that centre, and
// their display meshes merged into the body's one mesh (seed 004's vertex list).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/body/material.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// A part's density when none is given: water's, 1 kg per litre.
inline constexpr double kDefaultPartDensity = 1000.0;  // [kg/m^3]

struct CompoundPart {
  Shape shape;                          // sphere, capsule, box, rounded box or convex hull
  // A hull's closed, outward-wound mesh in the part's frame (its mass properties are the
  // polyhedral integrals of it, and it is drawn); unused for the other shapes.
  std::shared_ptr<const Mesh> mesh;
  Vec3 position = Vec3::Zero();         // the part frame's origin, in the caller's frame [m]
  Quat orientation = Quat::Identity();  // part frame to the caller's frame (unit)
  double density = kDefaultPartDensity; // [kg/m^3] > 0
  Material material;
  CollisionFilter filter;
};

// The parts' centre of mass becomes the body origin, with the caller's axes: the caller's frame
// is the body's FileFrame (p_caller = p_body + centre). With `totalMass` [kg], every density is
// scaled by one factor so that the parts weigh it together. Throws std::invalid_argument, naming
// the part, on no parts, more than kMaxCompoundChildren, a non-convex mesh part, a hull without
// its mesh or with a mesh wound inward, a density or mass that is not positive and finite.
BodyDef compoundBodyDef(const std::vector<CompoundPart>& parts, const std::string& name = "body",
                        std::optional<double> totalMass = std::nullopt);

}  // namespace rbsim
