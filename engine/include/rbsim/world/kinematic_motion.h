#pragma once
// Prescribed motion of a kinematic body (seed 000's "infinite mass kinematic objects"): turning
// about an axis through any point (a washer's drum, a turntable, a windmill), or following
// keyframes (a lift, a door, a scripted platform). Each step the World sets the body's velocity
// and angular velocity so that the step carries it exactly onto the path's pose at the step's
// end; bodies resting on it see that velocity at their contacts and are carried by friction
// (as Box2D's b2Body_SetTargetTransform and Jolt's MoveKinematic).
#include <string>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct Keyframe {
  double time = 0.0;                   // [s]
  Vec3 position = Vec3::Zero();        // of the centre of mass, world frame [m]
  Quat orientation = Quat::Identity(); // body to world (unit)
};

struct KinematicMotion {
  enum class Kind { Pivot, Keyframes };
  BodyId body;
  Kind kind = Kind::Pivot;
  // Pivot: the body turns at `angularVelocity` (world frame, its direction the axis) about the
  // axis through `pivot`, from where it is when the motion starts.
  Vec3 pivot = Vec3::Zero();            // [m]
  Vec3 angularVelocity = Vec3::Zero();  // [rad/s]
  // Keyframes, in increasing time: the pose between two keys is interpolated (position linearly,
  // orientation by slerp); before the first key the body moves to it from where it stands, and
  // after the last it rests there, unless `loop` starts the keys over every
  // (last time - first time) seconds.
  std::vector<Keyframe> keys;
  bool loop = false;
};

// Empty when the motion is usable; otherwise what is wrong, naming the field ("keys[2].time: ...").
std::string checkKinematicMotion(const KinematicMotion& motion);

// The pose the motion prescribes at time t (keyframes only).
Keyframe keyframePoseAt(const KinematicMotion& motion, double t);

}  // namespace rbsim
