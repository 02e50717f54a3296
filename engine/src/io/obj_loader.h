#pragma once
// Wavefront OBJ meshes through tinyobjloader (Debian's libtinyobjloader, double precision).
#include <cstddef>
#include <cstdint>
#include <string>

#include "rbsim/geometry/mesh.h"

namespace rbsim {

// A mesh file larger than this is refused before it is read: 256 MB of text is ~8 million
// lines, far above kMaxMeshTriangles, so no mesh that may be loaded is this large.
inline constexpr std::uintmax_t kMaxObjFileBytes = 256ull * 1024 * 1024;  // [bytes]
// tinyobjloader keeps a face's corner count in 8 bits (a 256-corner face would read as 0 corners,
// a 259-corner one as a triangle), so longer faces are refused before it reads them.
inline constexpr std::size_t kMaxObjFaceCorners = 255;  // [corners]

// All shapes in the file merged into one triangle mesh; polygons are triangulated by ear
// clipping (geometry/polygon_triangulation.h). Throws InputError (file, field, what is wrong) for
// a missing or unreadable file, a folder, FIFO or device, a file over kMaxObjFileBytes, an empty
// file, a malformed 'v', 'vt', 'vn' or 'f' line (named by its line number), a face of fewer than
// 3 or more than kMaxObjFaceCorners corners, an index out of range, more than kMaxMeshVertices
// vertices or kMaxMeshTriangles triangles, a polygon that cannot be triangulated, or non-finite
// coordinates.
Mesh loadObj(const std::string& path);

// The same for the text of an OBJ file; `path` names it in messages.
Mesh parseObj(const std::string& text, const std::string& path);

}  // namespace rbsim
