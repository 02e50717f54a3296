#pragma once
// Scene-file parsing of the "planar" block: a 2D world of polygons (engine/planar) in the xy
// plane. Internal to scene/.
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim::scene_detail {

void parsePlanar(const JsonObject& root, Scene& scene);

}  // namespace rbsim::scene_detail
