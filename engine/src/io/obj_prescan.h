#pragma once
// A line check of OBJ text before tinyobjloader parses it. tinyobjloader stays the parser; this
// only refuses what it would silently misread: a missing or non-numeric coordinate ('v 1 2',
// 'v 1 abc 3' read as 0), an index that is not an integer ('f 1 x 3' read as index 0 -> an error
// without a line, '1.5' read as 1), an index past the int range (atoi overflows), a face of over
// 255 corners (its count is kept in 8 bits), a NUL or other control byte (its C-string parsing
// stops at a NUL). It also counts vertices and triangles against the mesh budget before any is
// stored.
#include <cstddef>
#include <string>

namespace rbsim {

struct ObjCounts {
  std::size_t vertices = 0;   // 'v' lines
  std::size_t triangles = 0;  // sum over 'f' lines of corners - 2
};

// Throws InputError(path, "line N", what was expected and what was found) for the first bad
// line, and InputError(path, "mesh", ...) when the counts exceed kMaxMeshVertices or
// kMaxMeshTriangles.
ObjCounts prescanObj(const std::string& text, const std::string& path);

}  // namespace rbsim
