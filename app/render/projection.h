#pragma once
// Where a world point lands on the image, without GL: the projection the renderer draws with,
// shared with the window's picking and with tests.
#include <limits>

#include <glm/glm.hpp>

#include "frame_data.h"

namespace rbsim::render {

// glm::perspective(fovY, width/height, near, far) * glm::lookAt(eye, target, up).
glm::mat4 viewProjection(const Camera& camera, int width, int height);

// The distance along the camera axis [m] of a depth-buffer value d in [0, 1] drawn with that
// projection's near and far planes: z = P32 / (2 d - 1 + P22), the inverse of the mapping
// glm::perspective's matrix and GL's default depth range give, which is z = n f / (f - d (f - n))
// (Khronos OpenGL wiki, "Depth Buffer Precision"). d = 1 is the cleared buffer, no surface: +inf.
// Its constants are computed once, for a whole image.
class DepthLinearizer {
 public:
  DepthLinearizer(float nearPlane, float farPlane);
  float operator()(double windowDepth) const {
    if (windowDepth >= 1.0) return kNoSurface;
    // In double: 2 d - 1 + P22 cancels near the far plane.
    return static_cast<float>(p32_ / (2.0 * windowDepth - 1.0 + p22_));
  }

 private:
  static constexpr float kNoSurface = std::numeric_limits<float>::infinity();
  double p22_, p32_;  // the matrix's entries, as float (what the frame was drawn with)
};

// One value: DepthLinearizer(nearPlane, farPlane)(windowDepth).
float linearDepth(double windowDepth, float nearPlane, float farPlane);

}  // namespace rbsim::render
