#pragma once
// view.sdf_slice: {"body": name, "axis": "x" | "y" | "z", "offset": m, "sweep_to": m}, a layer of
// one body's signed distance grid shown beside the scene (rbsim/scene/view_desc.h, SdfSliceDesc).
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim {

// Checked against the body's grid: it must have one, and both offsets must lie within its extent
// along the axis. InputError naming the file and the field.
SdfSliceDesc parseSdfSlice(const JsonObject& o, const Scene& scene);

}  // namespace rbsim
