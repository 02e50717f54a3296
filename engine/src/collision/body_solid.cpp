#include "rbsim/collision/body_solid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "shapes/implicit_shape.h"

namespace rbsim {

BodySolid bodySolidOf(const BodyDef& def) {
  if (!def.children.empty()) {
    auto children = std::make_shared<std::vector<ChildSolid>>();
    BodySolid out{FacePlanes{}, nullptr, def.surfaceSamples, std::nullopt, nullptr, nullptr, nullptr};
    for (const ChildShape& c : def.children) {
      ChildSolid part;
      part.rotation = c.orientation.toRotationMatrix();
      part.position = c.position;
      if (c.shape.isRound()) {
        part.round = c.shape;
      } else {
        part.convex = facePlanesOf(*c.mesh);
      }
      out.convex.boundingRadius = std::max(out.convex.boundingRadius, c.position.norm() + c.shape.boundingRadius());
      children->push_back(std::move(part));
    }
    out.children = std::move(children);
    return out;
  }
  // A sphere's or capsule's display mesh is inscribed in it: the exact surface answers instead,
  // and the faces of its 48 x 24 tessellation are never asked for (finding them took 2 ms a
  // ball, most of what adding one cost).
  if (def.shape && def.shape->isRound()) {
    BodySolid out{FacePlanes{}, def.sdf, def.surfaceSamples, *def.shape, nullptr, nullptr, nullptr};
    out.convex.boundingRadius = def.shape->boundingRadius();
    return out;
  }
  // A body with a grid is asked through it (querySurface): its faces would never be read, and
  // finding them took 44% of loading a 600,000-triangle implicit torus (issue 37).
  if (def.sdf) {
    BodySolid out{FacePlanes{}, def.sdf, def.surfaceSamples, std::nullopt, def.implicit, def.triangles, nullptr};
    for (const Vec3& p : def.mesh->vertices) out.convex.boundingRadius = std::max(out.convex.boundingRadius, p.norm());
    return out;
  }
  return BodySolid{facePlanesOf(*def.mesh), def.sdf, def.surfaceSamples, std::nullopt, def.implicit, def.triangles, nullptr};
}

SurfaceQuery querySurface(const BodySolid& shape, const Vec3& local) {
  if (shape.children) {
    // The union of the children: the least of their signed distances, with that child's normal.
    SurfaceQuery nearest{std::numeric_limits<double>::infinity(), Vec3::UnitY()};
    for (const ChildSolid& child : *shape.children) {
      const Vec3 inChild = child.rotation.transpose() * (local - child.position);
      SurfaceQuery q;
      if (child.round) {
        const auto [distance, normal] = child.round->roundDistance(inChild);
        q = {distance, normal};
      } else {
        const auto [face, distance] = nearestFace(child.convex, inChild);
        q = {distance, child.convex.normals[face]};
      }
      if (q.distance < nearest.distance) nearest = {q.distance, child.rotation * q.normal};
    }
    return nearest;
  }
  if (shape.round) {
    const auto [distance, normal] = shape.round->roundDistance(local);
    return {distance, normal};
  }
  if (shape.sdf) {
    // Seed 000 "Collision Detection": phi at the object-space point, grad phi / |grad phi| as the
    // normal. Where the gradient vanishes (the medial axis of a flat-bottomed interpolant), the
    // way out is taken as straight away from the body's centre.
    Vec3 gradient;
    double phi = shape.sdf->phiAndGradient(local, gradient);
    if (shape.implicit && phi <= kExactBandCells * shape.sdf->cellSize()) {
      phi = shape.implicit->phi(local);
      gradient = shape.implicit->gradient(local);
    }
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
