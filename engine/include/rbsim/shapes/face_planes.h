#pragma once
// A convex solid as the intersection of the inner half-spaces of its face planes, in body frame:
// exact for convex meshes (boxes, hulls), the convex core of a concave one. Point queries of
// bodies (collision/body_solid.h) start from it.
#include <cstddef>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct FacePlanes {
  std::vector<Vec3> normals;    // unit, outward
  std::vector<double> offsets;  // n . p = offset on the face [m]
  double boundingRadius = 0.0;  // every vertex within it of the body origin [m]
};
FacePlanes facePlanesOf(const Mesh& mesh);

// The face of the shape a body-frame point is least deep behind, and its signed distance to that
// face's plane: the signed distance to the convex set when the point is inside (< 0), a lower
// bound of it outside. Empty shapes give face 0 at -infinity.
struct FaceDistance {
  std::size_t face = 0;
  double distance = 0.0;  // [m]
};
FaceDistance nearestFace(const FacePlanes& shape, const Vec3& local);

}  // namespace rbsim
