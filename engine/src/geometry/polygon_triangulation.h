#pragma once
// Triangles from the polygonal faces of a mesh file. rbsim triangulates faces itself, after
// checking every index, because the OBJ library's own triangulation reads vertex coordinates
// through unchecked indices.
#include <cstdint>
#include <vector>

#include "rbsim/geometry/mesh.h"

namespace rbsim {

// Beyond this many corners a face is far more likely a corrupt file than a modelled polygon, and
// ear clipping costs up to O(n^3) per face.
inline constexpr std::size_t kMaxPolygonCorners = 256;

// Splits the simple polygon `corners` (indices into `vertices`, in order, counter-clockwise seen
// from outside) into corners.size() - 2 triangles of the same winding, appended to `out`, by ear
// clipping in the plane of the polygon's Newell normal (Eberly 2002, "Triangulation by Ear
// Clipping"). Returns false, appending nothing, when the polygon has no area (collinear or
// coincident corners) or is not simple (two edges that are not neighbours meet). Indices must
// be valid.
bool triangulatePolygon(const std::vector<Vec3>& vertices, const std::vector<std::uint32_t>& corners,
                        std::vector<Triangle>& out);

}  // namespace rbsim
