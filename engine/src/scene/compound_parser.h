#pragma once
// Scene-file parsing of what issue 40 added to a body: a compound body's "shapes", a shape's
// collision "filter", and a kinematic body's prescribed "motion". Internal to scene/.
#include <cstddef>

#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim::scene_detail {

// "filter": {"category": bits, "mask": bits, "group": integer}, each an unsigned 64-bit integer
// of category bits, or a signed 32-bit group (shapes/collision_filter.h); absent keys keep base's
// (the default filter's, or a running body's for World.set_body).
CollisionFilter parseFilter(const JsonObject& o, const CollisionFilter& base = {});

// "shapes": [{"type": "box" | "sphere" | "capsule" | "rounded_box", the type's size keys,
// "position", "orientation", "density", material keys, "filter"}, ...] into def (mesh, mass
// properties, children, file frame: body/compound_body.h); the body's "mass", when given, is the
// parts' total.
void parseCompoundShapes(const JsonObject& b, BodyDef& def);

// A kinematic body's "motion": {"pivot": [x, y, z], "angular_velocity": [wx, wy, wz]} or
// {"keyframes": [{"time", "position", "orientation"}, ...], "loop": bool}, appended to
// scene.motions for body `index`.
void parseMotion(const JsonObject& b, std::size_t index, Scene& scene);

}  // namespace rbsim::scene_detail
