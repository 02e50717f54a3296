#include "projection.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rbsim::render {

glm::mat4 viewProjection(const Camera& camera, int width, int height) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDegrees), aspect,
                                                camera.nearPlane, camera.farPlane);
  return projection * glm::lookAt(camera.eye, camera.target, camera.up);
}

}  // namespace rbsim::render
