#pragma once
// Wavefront OBJ meshes through tinyobjloader (Debian's libtinyobjloader, double precision).
#include <string>

#include "geometry/mesh.h"

namespace rbsim {

// All shapes in the file merged into one triangle mesh; polygons are triangulated by
// tinyobjloader. Throws InputError (file, "mesh", what is wrong) for a missing, unreadable or
// empty file, or non-finite coordinates.
Mesh loadObj(const std::string& path);

}  // namespace rbsim
