#pragma once
// What an interactive frame (window mode) adds to the renderer's ImGui pass: the pointer as the
// window saw it, and a callback that draws the control windows inside the same ImGui frame as
// the variables panel. The off-screen path passes none, so both paths draw with one renderer.
#include <functional>

namespace rbsim::render {

struct UiInput {
  float mouseX = -1.0f, mouseY = -1.0f;  // [px] from the top left; negative when outside
  bool mouseDown[3] = {false, false, false};  // left, right, middle
  float wheel = 0.0f;                    // notches since the last frame, + away from the user
  float deltaSeconds = 1.0f / 30.0f;     // wall time since the last frame [s], > 0
};

// The shortest frame time a window reports: ImGui asserts on a zero one [s].
inline constexpr float kMinFrameSeconds = 1e-3f;

struct UiFrame {
  UiInput input;
  std::function<void()> draw;  // ImGui calls; runs with the renderer's ImGui context current
};

}  // namespace rbsim::render
