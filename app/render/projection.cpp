#include "projection.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rbsim::render {

glm::mat4 viewProjection(const Camera& camera, int width, int height) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDegrees), aspect,
                                                camera.nearPlane, camera.farPlane);
  return projection * glm::lookAt(camera.eye, camera.target, camera.up);
}

DepthLinearizer::DepthLinearizer(float nearPlane, float farPlane) {
  // In float, as glm::perspective computes them: inverting the rounded mapping the frame was drawn
  // with, not the exact one, keeps the error at the buffer's step.
  const float n = nearPlane, f = farPlane;
  p22_ = static_cast<double>(-(f + n) / (f - n));
  p32_ = static_cast<double>(-(2.0f * f * n) / (f - n));
}

float linearDepth(double windowDepth, float nearPlane, float farPlane) {
  return DepthLinearizer(nearPlane, farPlane)(windowDepth);
}

}  // namespace rbsim::render
