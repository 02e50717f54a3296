#pragma once
// Wavefront OBJ meshes through tinyobjloader (Debian's libtinyobjloader, double precision).
#include <string>

#include "geometry/mesh.h"

namespace rbsim {

// All shapes in the file merged into one triangle mesh; polygons are triangulated by ear
// clipping (geometry/polygon_triangulation.h). Throws InputError (file, field, what is wrong) for
// a missing, unreadable or empty file, a face of fewer than 3 corners, an index out of range, a
// polygon that cannot be triangulated, or non-finite coordinates.
Mesh loadObj(const std::string& path);

// The same for the text of an OBJ file; `path` names it in messages.
Mesh parseObj(const std::string& text, const std::string& path);

}  // namespace rbsim
