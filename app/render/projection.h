#pragma once
// Where a world point lands on the image, without GL: the projection the renderer draws with,
// shared with the window's picking and with tests.
#include <glm/glm.hpp>

#include "frame_data.h"

namespace rbsim::render {

// glm::perspective(fovY, width/height, near, far) * glm::lookAt(eye, target, up).
glm::mat4 viewProjection(const Camera& camera, int width, int height);

// The distance along the camera axis [m] of a depth-buffer value d in [0, 1] drawn with that
// projection's near and far planes: z = P32 / (2 d - 1 + P22), the inverse of the mapping
// glm::perspective's matrix and GL's default depth range give, which is z = n f / (f - d (f - n))
// (Khronos OpenGL wiki, "Depth Buffer Precision"). d = 1 is the cleared buffer, no surface: +inf.
float linearDepth(double windowDepth, float nearPlane, float farPlane);

}  // namespace rbsim::render
