#pragma once
// The colour a body is drawn in, found by its name in the scene's colours (rbsim/scene/view_desc.h,
// BodyColors): the engine keeps no colour, so a body made while stepping is matched by the name it
// was given. A listed body has its own; a spawner's copy NAME_k its spawner's; a fracture piece
// BODY/k its body's; any other body (a ragdoll's bone, one added without a colour) the default.
#include <string>

#include "rbsim/math/types.h"
#include "rbsim/scene/view_desc.h"

namespace rbsim::app {

Vec3 bodyColor(const BodyColors& colors, const std::string& name);

}  // namespace rbsim::app
