#include "projection.h"

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace rbsim::render {

glm::mat4 viewProjection(const Camera& camera, int width, int height) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDegrees), aspect,
                                                camera.nearPlane, camera.farPlane);
  return projection * glm::lookAt(camera.eye, camera.target, camera.up);
}

float linearDepth(double windowDepth, float nearPlane, float farPlane) {
  if (windowDepth >= 1.0) return std::numeric_limits<float>::infinity();
  // The matrix's own entries, in float as glm::perspective computes them: inverting the rounded
  // mapping the frame was drawn with, not the exact one, keeps the error at the buffer's step.
  const float n = nearPlane, f = farPlane;
  const float p22 = -(f + n) / (f - n);
  const float p32 = -(2.0f * f * n) / (f - n);
  // In double: 2 d - 1 + P22 cancels near the far plane.
  return static_cast<float>(static_cast<double>(p32) / (2.0 * windowDepth - 1.0 + static_cast<double>(p22)));
}

}  // namespace rbsim::render
