#include "window/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace rbsim::app {

OrbitCamera::OrbitCamera(const render::Camera& scene) : camera_(scene) {
  const glm::vec3 offset = scene.eye - scene.target;
  distance_ = std::max(kMinDistance, glm::length(offset));
  yaw_ = std::atan2(offset.x, offset.z);
  pitch_ = std::asin(std::clamp(offset.y / distance_, -1.0f, 1.0f));
}

void OrbitCamera::place() {
  const glm::vec3 direction(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_));
  camera_.eye = camera_.target + distance_ * direction;
  camera_.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
  yaw_ -= kOrbitRadiansPerPixel * dxPixels;
  pitch_ = std::clamp(pitch_ + kOrbitRadiansPerPixel * dyPixels, kMinPitch, kMaxPitch);
  place();
}

void OrbitCamera::zoom(float notches) {
  distance_ = std::max(kMinDistance, distance_ * std::pow(kZoomPerNotch, notches));
  place();
}

void OrbitCamera::pan(float dxPixels, float dyPixels, int imageHeight) {
  // One pixel moves the target by the size of a pixel at the target's distance.
  const float metresPerPixel =
      2.0f * distance_ * std::tan(0.5f * glm::radians(camera_.fovYDegrees)) / static_cast<float>(imageHeight);
  const glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  const glm::vec3 up = glm::cross(right, forward);
  camera_.target += metresPerPixel * (-dxPixels * right + dyPixels * up);
  place();
}

}  // namespace rbsim::app
