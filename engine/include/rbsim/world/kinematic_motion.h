#pragma once
// Prescribed motion of a kinematic body (seed 000's "infinite mass kinematic objects"): turning
// about an axis through any point (a washer's drum, a turntable, a windmill), or following
// keyframes (a lift, a door, a scripted platform). Each step the World sets the body's velocity
// and angular velocity so that the step carries it exactly onto the path's pose at the step's
// end; bodies resting on it see that velocity at their contacts and are carried by friction
// (as Box2D's b2Body_SetTargetTransform and Jolt's MoveKinematic).
#include <cstddef>
#include <string>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

class World;

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

// The most keyframes a motion holds [1]: a key every step of 1/60 s for 27 minutes, 10 MB of keys.
// Without a bound a scene of a million keys loaded them all (the step finds its key by bisection,
// so their number costs memory and load time, not step time).
constexpr std::size_t kMaxKeyframes = 100000;

// Empty when the motion is usable; otherwise what is wrong, naming the field ("keys[2].time: ...").
std::string checkKinematicMotion(const KinematicMotion& motion);

// The pose the motion prescribes at time t (keyframes only), in O(log keys): the step's key by
// bisection (a scan from the first took 2.6 ms a step over 1e6 keys).
Keyframe keyframePoseAt(const KinematicMotion& motion, double t);

// A kinematic body's prescribed motion in `world`, from the next step on; replaces the body's
// earlier one. Throws std::invalid_argument on a bad motion (checkKinematicMotion) or a body not
// kinematic. Free functions over World, as spawners and ragdolls are (docs/architecture.md, "The World's surface").
void setKinematicMotion(World& world, const KinematicMotion& motion);
const std::vector<KinematicMotion>& kinematicMotions(const World& world);  // at most one per body

}  // namespace rbsim
