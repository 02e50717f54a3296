#pragma once
// Scripted inputs of a scene: forces over a time window, and poses set by hand at an instant
// (seed 004 "TO DO: change values of x and R and redraw").
#include <cstddef>
#include <optional>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

enum class Frame { World, Body };

// A force f applied at point p for start <= t < end, t being the time at the start of a step.
struct ScriptedForce {
  BodyId body;
  Vec3 force = Vec3::Zero();     // [N], in forceFrame
  Vec3 point = Vec3::Zero();     // [m], in pointFrame (body frame: relative to the centre of mass)
  Frame forceFrame = Frame::World;
  Frame pointFrame = Frame::Body;
  double start = 0.0;            // [s]
  double end = 0.0;              // [s]
};

// At the first step starting at or after `time`, the given fields are set by hand.
struct PoseEvent {
  BodyId body;
  double time = 0.0;  // [s]
  std::optional<Vec3> position;
  std::optional<Quat> orientation;
  std::optional<Vec3> velocity;
  std::optional<Vec3> angularVelocity;
};

}  // namespace rbsim
