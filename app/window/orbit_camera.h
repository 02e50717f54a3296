#pragma once
// The window's camera: orbits about a target (yaw about world y, pitch above the ground plane),
// zooms by distance, pans in the view plane. Until the user moves it, it is exactly the scene's
// camera, so a window frame and an off-screen frame of the same step are the same image.
#include <glm/glm.hpp>

#include "render/frame_data.h"

namespace rbsim::app {

inline constexpr float kOrbitRadiansPerPixel = 0.008f;  // [rad/px] of pointer motion
inline constexpr float kZoomPerNotch = 0.9f;            // distance factor per wheel notch [1]
inline constexpr float kMinPitch = -1.45f;              // [rad], short of straight down
inline constexpr float kMaxPitch = 1.45f;               // [rad], short of straight up
inline constexpr float kMinDistance = 0.2f;             // [m] from the target

class OrbitCamera {
 public:
  explicit OrbitCamera(const render::Camera& scene);

  void orbit(float dxPixels, float dyPixels);
  void zoom(float notches);  // + moves closer
  void pan(float dxPixels, float dyPixels, int imageHeight);

  const render::Camera& camera() const { return camera_; }

 private:
  void place();  // eye from target, yaw, pitch, distance

  render::Camera camera_;
  float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 1.0f;
};

}  // namespace rbsim::app
