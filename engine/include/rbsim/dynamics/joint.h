#pragma once
// Joints: a ball (spherical, pivot) joint holds a point of a body at a point of another body or
// of the world, optionally within a cone about an axis and a twist range about it (a shoulder);
// a hinge (revolute) joint also keeps the two bodies' copies of an axis aligned, so the body turns
// about that axis only, with an optional motor and optional angle limits; a prismatic (slider)
// joint lets the body slide along an axis only, with optional motor and translation limits; a
// weld (fixed) joint holds the relative position and orientation, optionally soft. Every type but
// the weld takes a spring toward where it was added and a friction (a capped motor of speed 0).
// Seed 004: "for a hinged object, x is the position of the pivot/hinge". Solved by the soft step
// (dynamics/soft_step_joints.cpp, dynamics/joints/), as Box2D v3 solves its joints (src/joint.c,
// revolute_joint.c, prismatic_joint.c, weld_joint.c) and Box3D its spherical joint
// (src/spherical_joint.c: cone and twist).
#include <string>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

// body_b of a joint held by the world: the id of no body.
inline constexpr BodyId kWorldAnchor{};

struct JointDef {
  enum class Type { Ball, Hinge, Prismatic, Weld };
  Type type = Type::Ball;
  std::string name;
  BodyId bodyA;                      // the jointed body (dynamic)
  BodyId bodyB = kWorldAnchor;       // the body it hangs on, or the world
  Vec3 anchor = Vec3::Zero();        // the pivot, world frame, where the bodies are when it is added [m]
  // Hinge axis, prismatic slide direction, ball's cone and twist axis; world frame at that time, unit.
  Vec3 axis = Vec3::UnitZ();
  bool motor = false;                // hinge and prismatic
  double motorSpeed = 0.0;           // of A relative to B: about the axis [rad/s]; prismatic along it [m/s]
  double maxMotorTorque = 0.0;       // hinge [N m]
  double maxMotorForce = 0.0;        // prismatic [N]
  // Hinge: the angle; ball: the twist about the axis (both of A relative to B, from where it was
  // added). Prismatic: the translation of A's anchor from B's along the axis.
  bool limits = false;
  double lowerAngle = 0.0;           // [rad]
  double upperAngle = 0.0;           // [rad]
  double lowerTranslation = 0.0;     // prismatic [m]
  double upperTranslation = 0.0;     // prismatic [m]
  // Ball: A's copy of the axis stays within coneAngle of B's (the swing, 0 to pi).
  bool coneLimit = false;
  double coneAngle = 0.0;            // half-angle [rad]
  // A spring toward where the joint was added (angle 0, translation 0, the ball's rotation then):
  // a soft constraint of this natural frequency and damping ratio for the joint's effective mass.
  bool spring = false;
  double springHertz = 0.0;          // [Hz]
  double springDampingRatio = 0.0;   // [1]
  // Joint friction, Box3D's shared/human.c way: a motor of target speed 0 whose impulse is capped
  // at h friction. Hinge and ball [N m], prismatic [N]; 0 is none. A weld has none.
  double friction = 0.0;
  // Weld softness: 0 Hz is as rigid as the solver allows (the joints' own softness), Box2D v3's
  // b2WeldJointDef linearHertz, angularHertz.
  double linearHertz = 0.0;          // [Hz]
  double linearDampingRatio = 0.0;   // [1]
  double angularHertz = 0.0;         // [Hz]
  double angularDampingRatio = 0.0;  // [1]
  bool collideConnected = false;     // whether bodies A and B collide with each other
};

// The joint as the World keeps it: its definition, the anchor and axis carried by each side, and
// the impulses of its last substep (the warm start of the next step). Side "base" is body B or
// the world, side "moving" body A, so the hinge angle and the motor speed are A's turning
// relative to B. The bodies are def.bodyA and def.bodyB, by id: whoever needs their indices
// resolves them through the World's id table when it reads them (the soft step once per step, as
// Box2D v3's b2PrepareJointsTask resolves a joint's body ids), so a removal renumbers nothing here.
struct Joint {
  JointDef def;
  Vec3 localAnchorBase = Vec3::Zero();    // base's body frame, from its centre of mass; world frame for the world [m]
  Vec3 localAnchorMoving = Vec3::Zero();  // body A's frame, from its centre of mass [m]
  Vec3 localAxisBase = Vec3::UnitZ();     // unit, base's frame
  Vec3 localAxisMoving = Vec3::UnitZ();   // unit, A's frame
  Quat referenceRotation = Quat::Identity();  // q_base^-1 q_A when added: the angle's zero
  // Warm start: the impulses of the last substep, world frame. Prismatic: linear ones [N s] where
  // the others are angular [N m s].
  Vec3 linearImpulse = Vec3::Zero();      // on the point; prismatic: across the axis [N s]
  // Hinge: holding the axes aligned, across the axis; prismatic and weld: holding the orientation.
  Vec3 angularImpulse = Vec3::Zero();     // [N m s]
  double motorImpulse = 0.0;              // about (prismatic: along) the axis
  double lowerImpulse = 0.0, upperImpulse = 0.0;  // of the limits (ball: twist), >= 0
  double swingImpulse = 0.0;              // of the ball's cone, >= 0 [N m s]
  // Hinge and prismatic: along the axis; ball: the angular vector.
  Vec3 springImpulse = Vec3::Zero();
  Vec3 frictionImpulse = Vec3::Zero();
};
// 528 bytes, 8.25 cache lines of 64 (measured with offsetof): the def (264, its name a 32-byte
// std::string, its body ids 16), anchors and axes (96), the reference rotation aligned to 16 (40),
// then the warm-start impulses (128, bytes 400 to 527), which the soft step's sweeps read and
// write every substep (the sweep of a plain ball joint reads only these, soft_step_solver.h
// JointConstraint): in an array that starts on a line, joint k's start 16 (k + 1) mod 64 bytes
// into one, so they span three lines for three joints in four and two for the fourth (2.75 on
// average; 2.5 at 544 bytes, when Joint kept the bodies' indices beside their ids). Checked where
// std::string is 32 bytes (libstdc++, MSVC's release library).
static_assert(sizeof(std::string) != 32 || sizeof(Joint) == 528, "Joint's size: see the comment above");

// The hinge angle of A relative to the base about the base's axis [rad], in (-pi, pi]: the twist
// of q_base^-1 q_A q_ref^-1 about the base's local axis.
double hingeAngle(const Joint& joint, const Quat& base, const Quat& moving);

// The rotation of A relative to the base since the joint was added, as a rotation vector in world
// frame [rad]: the log of q_A (q_base q_ref)^-1, angle in [0, pi]. Zero where it was added; its
// rate is omega_A - omega_base.
Vec3 relativeRotation(const Joint& joint, const Quat& base, const Quat& moving);

// The ball's swing: the angle between the base's copy of the axis and A's [rad], in [0, pi].
double swingAngle(const Joint& joint, const Quat& base, const Quat& moving);

}  // namespace rbsim
