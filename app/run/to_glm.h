#pragma once
// Engine doubles to the renderer's floats: the one conversion every frame builder uses.
#include <glm/glm.hpp>

#include "rbsim/math/types.h"

namespace rbsim::app {

inline glm::vec3 toGlm(const Vec3& v) {
  return glm::vec3(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
}

}  // namespace rbsim::app
