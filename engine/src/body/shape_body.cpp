#include "rbsim/body/shape_body.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "rbsim/geometry/mesh_generators.h"

namespace rbsim {

Mesh displayMeshOf(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::Sphere: return makeUvSphere(shape.radius, kDisplaySegments, kDisplayRings);
    case ShapeType::Capsule: return makeCapsule(shape.radius, 2.0 * shape.halfLength, kDisplaySegments, kDisplayRings);
    case ShapeType::Box: return makeBox(2.0 * shape.halfExtents);
    case ShapeType::RoundedBox: return makeRoundedBox(shape.halfExtents, shape.radius, kDisplayBandSegments);
    case ShapeType::ConvexHull:
    case ShapeType::Mesh: break;
  }
  throw std::invalid_argument(std::string("displayMeshOf: a ") + shapeTypeName(shape.type) + " is drawn as its own mesh");
}

BodyDef shapeBodyDef(const Shape& shape, double mass, const std::string& name) {
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    throw std::invalid_argument("body '" + name + "': mass must be a positive finite number [kg]");
  }
  BodyDef def;
  def.name = name;
  def.mesh = std::make_shared<const Mesh>(displayMeshOf(shape));
  def.mass = mass;
  def.inertiaBody = roundOrBoxInertia(shape, mass);
  def.shape = shape;
  return def;
}

}  // namespace rbsim
