#pragma once
// Where a world point lands on the image, without GL: the projection the renderer draws with,
// shared with the window's picking and with tests.
#include <glm/glm.hpp>

#include "frame_data.h"

namespace rbsim::render {

// glm::perspective(fovY, width/height, near, far) * glm::lookAt(eye, target, up).
glm::mat4 viewProjection(const Camera& camera, int width, int height);

}  // namespace rbsim::render
