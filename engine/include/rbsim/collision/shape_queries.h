#pragma once
// The exact queries of one collision shape, in its body frame (origin at the centre of mass),
// beside Shape::support: the signed distance of a point and the first hit of a ray. Sphere,
// capsule, box and rounded box answer in closed form, exactly; a convex hull through its support
// mapping (GJK outside, EPA inside, GJK ray casting), to 1e-9 m. A ShapeType::Mesh's
// solid is its signed distance grid, not a shape's: its point queries go through the body's
// BodySolid (collision/body_solid.h), and these throw for it.
#include <optional>

#include "rbsim/math/types.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

struct ShapeDistance {
  double distance = 0.0;        // to the surface, < 0 inside [m]
  Vec3 normal = Vec3::UnitY();  // outward unit normal at the nearest surface point
};
// Throws std::invalid_argument for a ShapeType::Mesh.
ShapeDistance signedDistance(const Shape& shape, const Vec3& local);

struct RayHit {
  double fraction = 0.0;        // the hit is origin + fraction * direction
  Vec3 normal = Vec3::UnitY();  // outward unit normal there
};
// The first point of the solid on origin + s direction, 0 <= s <= maxFraction (a ray that starts
// inside hits at 0, with the normal of the nearest surface); empty when it misses or direction is
// zero. Throws std::invalid_argument for a ShapeType::Mesh.
std::optional<RayHit> rayCast(const Shape& shape, const Vec3& origin, const Vec3& direction, double maxFraction = 1.0);

}  // namespace rbsim
