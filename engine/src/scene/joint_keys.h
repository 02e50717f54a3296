#pragma once
// The keys of a joint block, by joint type (rbsim/scene/scene_keys.h): names, types, ranges and a
// line each, with the physical bounds joint_parser.cpp checks them against.
#include <cmath>
#include <cstddef>

#include "rbsim/dynamics/joint_ranges.h"
#include "rbsim/math/types.h"
#include "rbsim/scene/scene_keys.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

// A motor's physical ranges (kMaxMotorSpeed, kMaxMotorTorque, kMaxMotorForce) are the World's
// own checks' (dynamics/joint_ranges.h), so a scene and setJointMotor refuse the same values.
// A slider motor's force and a joint's friction share that bound ([N], [N m]); a spring's
// frequency stops at 1e6 Hz, beyond any substep rate a scene can ask for (it would be rigid).
inline constexpr double kMaxJointFriction = kMaxMotorTorque;  // [N m] or [N]
inline constexpr double kMaxJointHertz = 1e6;    // [Hz]
// A damping ratio past 1e6 is a typo: at 1 it is already critically damped.
inline constexpr double kMaxJointDampingRatio = 1e6;  // [1]

inline constexpr SceneKey kHingeMotorKeyTable[] = {
    key("speed", KeyType::Number, "target turning rate [rad/s]").magnitude(kMaxMotorSpeed).needed(),
    key("max_torque", KeyType::Number, "largest torque [N m]").within(0.0, kMaxMotorTorque).needed(),
};
inline constexpr KeyTable kHingeMotorKeys{kHingeMotorKeyTable, "a motor driving the hinge"};
inline constexpr SceneKey kSliderMotorKeyTable[] = {
    key("speed", KeyType::Number, "target sliding speed [m/s]").magnitude(kMaxMotorSpeed).needed(),
    key("max_force", KeyType::Number, "largest force [N]").within(0.0, kMaxMotorForce).needed(),
};
inline constexpr KeyTable kSliderMotorKeys{kSliderMotorKeyTable, "a motor driving the slider"};
inline constexpr SceneKey kJointSpringKeyTable[] = {
    key("hertz", KeyType::Number, "natural frequency [Hz]").above(0.0).atMost(kMaxJointHertz).needed(),
    key("damping_ratio", KeyType::Number, "damping ratio").within(0.0, kMaxJointDampingRatio),
};
inline constexpr KeyTable kJointSpringKeys{kJointSpringKeyTable, "a spring towards the joint's rest pose"};

// Every joint's keys; a table per type lists the ones that type takes.
#define RBSIM_JOINT_COMMON_KEYS                                                                                  \
  key("name", KeyType::String, "the joint's name"), key("type", KeyType::String, "the joint's kind").needed(),  \
      key("body_a", KeyType::String, "a dynamic body's name").needed(),                                        \
      key("body_b", KeyType::String, "another body's name (none: the world)"),                                 \
      key("anchor", KeyType::Vec3, "world point at t = 0 [m]").magnitude(kMaxCoordinate).needed()
#define RBSIM_JOINT_AXIS_KEY key("axis", KeyType::Vec3, "the axis, world frame at t = 0, non-zero")
#define RBSIM_JOINT_FRICTION_KEY key("friction", KeyType::Number, "joint friction [N m, or N for a slider]").within(0.0, kMaxJointFriction)
#define RBSIM_JOINT_SPRING_KEY key("spring", KeyType::Object, "a spring towards the rest pose").of(kJointSpringKeys)
#define RBSIM_JOINT_COLLIDE_KEY key("collide_connected", KeyType::Boolean, "let the two bodies collide")
#define RBSIM_WELD_KEYS                                                                                          \
  key("linear_hertz", KeyType::Number, "weld's linear softness [Hz] (0: rigid)").within(0.0, kMaxJointHertz), \
      key("linear_damping_ratio", KeyType::Number, "weld's linear damping ratio").within(0.0, kMaxJointDampingRatio), \
      key("angular_hertz", KeyType::Number, "weld's angular softness [Hz] (0: rigid)").within(0.0, kMaxJointHertz), \
      key("angular_damping_ratio", KeyType::Number, "weld's angular damping ratio").within(0.0, kMaxJointDampingRatio)

inline constexpr SceneKey kJointKeyTable[] = {
    RBSIM_JOINT_COMMON_KEYS, RBSIM_JOINT_AXIS_KEY,
    key("motor", KeyType::Object, "a motor (hinge, prismatic)"),
    key("limits", KeyType::NumberArray, "[lower, upper] angles [rad] or translations [m] (hinge, prismatic)").sized(2),
    key("cone", KeyType::Number, "a ball joint's cone half-angle [rad]").within(0.0, kPi),
    key("twist", KeyType::NumberArray, "a ball joint's [lower, upper] twist [rad]").sized(2).magnitude(kPi),
    RBSIM_JOINT_SPRING_KEY, RBSIM_JOINT_FRICTION_KEY, RBSIM_WELD_KEYS, RBSIM_JOINT_COLLIDE_KEY,
};
inline constexpr KeyTable kJointKeys{kJointKeyTable, "a joint between two bodies, its keys by \"type\""};

inline constexpr SceneKey kBallJointKeyTable[] = {
    RBSIM_JOINT_COMMON_KEYS, RBSIM_JOINT_AXIS_KEY,
    key("cone", KeyType::Number, "the cone's half-angle about the axis [rad]").within(0.0, kPi),
    key("twist", KeyType::NumberArray, "[lower, upper] twist about the axis [rad]").sized(2).magnitude(kPi),
    RBSIM_JOINT_SPRING_KEY, RBSIM_JOINT_FRICTION_KEY, RBSIM_JOINT_COLLIDE_KEY,
};
inline constexpr SceneKey kHingeJointKeyTable[] = {
    RBSIM_JOINT_COMMON_KEYS, RBSIM_JOINT_AXIS_KEY.needed(),
    key("motor", KeyType::Object, "a motor").of(kHingeMotorKeys),
    key("limits", KeyType::NumberArray, "[lower, upper] angles [rad], lower <= upper").sized(2).magnitude(kPi),
    RBSIM_JOINT_SPRING_KEY, RBSIM_JOINT_FRICTION_KEY, RBSIM_JOINT_COLLIDE_KEY,
};
inline constexpr SceneKey kPrismaticJointKeyTable[] = {
    RBSIM_JOINT_COMMON_KEYS, RBSIM_JOINT_AXIS_KEY.needed(),
    key("motor", KeyType::Object, "a motor").of(kSliderMotorKeys),
    key("limits", KeyType::NumberArray, "[lower, upper] translations [m], lower <= upper").sized(2).magnitude(kMaxCoordinate),
    RBSIM_JOINT_SPRING_KEY, RBSIM_JOINT_FRICTION_KEY, RBSIM_JOINT_COLLIDE_KEY,
};
inline constexpr SceneKey kWeldJointKeyTable[] = {RBSIM_JOINT_COMMON_KEYS, RBSIM_WELD_KEYS, RBSIM_JOINT_COLLIDE_KEY};
inline constexpr KeyTable kBallJointKeys{kBallJointKeyTable}, kHingeJointKeys{kHingeJointKeyTable},
    kPrismaticJointKeys{kPrismaticJointKeyTable}, kWeldJointKeys{kWeldJointKeyTable};
inline constexpr KeyVariant kJointVariants[] = {
    {"ball", &kBallJointKeys, "a ball-and-socket joint, with an optional cone and twist"},
    {"hinge", &kHingeJointKeys, "a hinge about an axis"},
    {"prismatic", &kPrismaticJointKeys, "a slider along an axis"},
    {"weld", &kWeldJointKeys, "a weld, rigid or soft"},
};

#undef RBSIM_JOINT_COMMON_KEYS
#undef RBSIM_JOINT_AXIS_KEY
#undef RBSIM_JOINT_FRICTION_KEY
#undef RBSIM_JOINT_SPRING_KEY
#undef RBSIM_JOINT_COLLIDE_KEY
#undef RBSIM_WELD_KEYS

}  // namespace rbsim::scene_detail
