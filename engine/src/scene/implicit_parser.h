#pragma once
// Scene-file parsing of implicit and CSG shapes (shapes/implicit_shape.h). Internal to scene/.
//   {"type": "implicit", "function": "sphere" | "ellipsoid" | "torus" | "box" | "capsule" |
//    "cylinder", its lengths [m], "position": [m], "orientation": {...}}
//   {"type": "csg", "op": "union" | "intersection" | "difference", "a": SHAPE, "b": SHAPE,
//    "position", "orientation"}
// with "resolution" (cells along the longest side, default kDefaultImplicitResolution) on the
// outermost one only.
#include "rbsim/scene/json_fields.h"
#include "shapes/implicit_shape.h"

namespace rbsim::scene_detail {

// Parses `shape` (type "implicit" or "csg"), failing naming the field for every wrong one: an
// unknown function or operation, a missing or non-positive length, a torus's tube not thinner than
// its ring, nesting deeper than kMaxCsgDepth, a resolution out of range or over budget.
ImplicitShape parseImplicitShape(const JsonObject& shape);

// Meshes the shape (file frame), failing naming "op" (or "function") when the solid is empty and
// "resolution" when the mesh would pass a mesh file's limits.
ImplicitMeshing meshImplicitShapeOrFail(const JsonObject& shape, const ImplicitShape& implicit);

}  // namespace rbsim::scene_detail
