#include "collision/body_shape.h"

#include <cmath>
#include <limits>

namespace rbsim {

namespace {
// Faces whose normals and offsets agree this closely are one plane (a box face's two triangles).
constexpr double kSamePlaneTolerance = 1e-9;  // [1] and [m]
}  // namespace

ConvexShape convexShapeOf(const Mesh& mesh) {
  ConvexShape shape;
  for (const Vec3& p : mesh.vertices) shape.boundingRadius = std::max(shape.boundingRadius, p.norm());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    if (!(n.norm() > 0.0)) continue;  // degenerate: no plane
    const Vec3 unit = n.normalized();
    const double offset = unit.dot(a);
    bool known = false;
    for (std::size_t f = 0; f < shape.normals.size() && !known; ++f) {
      known = (shape.normals[f] - unit).norm() < kSamePlaneTolerance &&
              std::abs(shape.offsets[f] - offset) < kSamePlaneTolerance;
    }
    if (!known) {
      shape.normals.push_back(unit);
      shape.offsets.push_back(offset);
    }
  }
  return shape;
}

FaceDistance nearestFace(const ConvexShape& shape, const Vec3& local) {
  FaceDistance out{0, -std::numeric_limits<double>::infinity()};
  for (std::size_t f = 0; f < shape.normals.size(); ++f) {
    const double d = shape.normals[f].dot(local) - shape.offsets[f];
    if (d > out.distance) out = {f, d};
  }
  return out;
}

BodyShape bodyShapeOf(const BodyDef& def) { return BodyShape{convexShapeOf(*def.mesh), def.sdf, def.surfaceSamples}; }

SurfaceQuery querySurface(const BodyShape& shape, const Vec3& local) {
  if (shape.sdf) {
    // Seed 000 "Collision Detection": phi at the object-space point, grad phi / |grad phi| as the
    // normal. Where the gradient vanishes (the medial axis of a flat-bottomed interpolant), the
    // way out is taken as straight away from the body's centre.
    Vec3 gradient;
    const double phi = shape.sdf->phiAndGradient(local, gradient);
    const double length = gradient.norm();
    if (length > 0.0) return {phi, gradient / length};
    const double radial = local.norm();
    return {phi, radial > 0.0 ? Vec3(local / radial) : Vec3::UnitY()};
  }
  if (shape.convex.normals.empty()) return {std::numeric_limits<double>::infinity(), Vec3::UnitY()};
  // The signed distance to the convex set is at least the largest face distance; inside, it is
  // exactly that, and the face it belongs to is the nearest way out.
  const auto [face, distance] = nearestFace(shape.convex, local);
  return {distance, shape.convex.normals[face]};
}

}  // namespace rbsim
