#pragma once
// Scripted inputs of a scene: forces over a time window, and poses set by hand at an instant
// (seed 004 "TO DO: change values of x and R and redraw").
#include <cstddef>
#include <optional>
#include <utility>

#include "rbsim/body/body_id.h"
#include "rbsim/body/rigid_body.h"
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
inline bool isActive(const ScriptedForce& f, double t) { return t >= f.start && t < f.end; }
// (application point, force), both in world frame, for the body's pose now.
std::pair<Vec3, Vec3> inWorldFrame(const ScriptedForce& f, const RigidBody& body);

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
