#pragma once
// Joints: a ball (spherical, pivot) joint holds a point of a body at a point of another body or
// of the world; a hinge (revolute) joint also keeps the two bodies' copies of an axis aligned, so
// the body turns about that axis only, with an optional motor and optional angle limits.
// Seed 004: "for a hinged object, x is the position of the pivot/hinge". Solved by the soft step
// (dynamics/soft_step_joints.cpp), as Box2D v3 solves its joints (src/joint.c, revolute_joint.c).
#include <cstddef>
#include <limits>
#include <string>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

// body_b of a joint held by the world: the id of no body.
inline constexpr BodyId kWorldAnchor{};
// Joint::b of a joint held by the world.
inline constexpr std::size_t kWorldIndex = std::numeric_limits<std::size_t>::max();

struct JointDef {
  enum class Type { Ball, Hinge };
  Type type = Type::Ball;
  std::string name;
  BodyId bodyA;                      // the jointed body (dynamic)
  BodyId bodyB = kWorldAnchor;       // the body it hangs on, or the world
  Vec3 anchor = Vec3::Zero();        // the pivot, world frame, where the bodies are when it is added [m]
  Vec3 axis = Vec3::UnitZ();         // hinge axis, world frame at that time, unit
  bool motor = false;
  double motorSpeed = 0.0;           // target angular speed of body A relative to B about the axis [rad/s]
  double maxMotorTorque = 0.0;       // [N m]
  bool limits = false;
  double lowerAngle = 0.0;           // of body A relative to B about the axis, from where it was added [rad]
  double upperAngle = 0.0;           // [rad]
  bool collideConnected = false;     // whether bodies A and B collide with each other
};

// The joint as the World keeps it: its definition, the anchor and axis carried by each side, and
// the impulses of its last substep (the warm start of the next step). Side "base" is body B or
// the world, side "moving" body A, so the hinge angle and the motor speed are A's turning
// relative to B.
struct Joint {
  JointDef def;
  // The bodies' indices in World::bodies() now (World::destroyBody keeps them up to date), for
  // the solver; b is kWorldIndex for the world.
  std::size_t a = 0;
  std::size_t b = kWorldIndex;
  Vec3 localAnchorBase = Vec3::Zero();    // base's body frame, from its centre of mass; world frame for the world [m]
  Vec3 localAnchorMoving = Vec3::Zero();  // body A's frame, from its centre of mass [m]
  Vec3 localAxisBase = Vec3::UnitZ();     // unit, base's frame
  Vec3 localAxisMoving = Vec3::UnitZ();   // unit, A's frame
  Quat referenceRotation = Quat::Identity();  // q_base^-1 q_A when added: the angle's zero
  // Warm start: the impulses of the last substep, world frame.
  Vec3 linearImpulse = Vec3::Zero();      // on the point [N s]
  Vec3 angularImpulse = Vec3::Zero();     // holding the axes aligned, perpendicular to the axis [N m s]
  double motorImpulse = 0.0;              // about the axis [N m s]
  double lowerImpulse = 0.0, upperImpulse = 0.0;  // of the limits, >= 0 [N m s]
};

// The hinge angle of A relative to the base about the base's axis [rad], in (-pi, pi]: the twist
// of q_base^-1 q_A q_ref^-1 about the base's local axis.
double hingeAngle(const Joint& joint, const Quat& base, const Quat& moving);

}  // namespace rbsim
