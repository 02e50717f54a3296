#pragma once
// The keys of spawn blocks, ragdolls and the kill volume (rbsim/scene/scene_keys.h): names, types,
// ranges and a line each. spawn.cpp, ragdoll_parser.cpp and scene.cpp read them.
#include "rbsim/scene/scene_keys.h"
#include "scene/body_keys.h"
#include "scene/input_ranges.h"
#include "scene/joint_keys.h"

namespace rbsim::scene_detail {

// More bodies than this in one block is almost certainly a typo for a smaller number.
inline constexpr int kMaxSpawnCount = 100000;
// A figure's size as a factor on the 1.8 m figure: a 9 cm doll to a 36 m giant.
inline constexpr double kMinRagdollScale = 0.05;  // [1]
inline constexpr double kMaxRagdollScale = 20.0;  // [1]

inline constexpr SceneKey kRegionKeyTable[] = {
    key("min", KeyType::Vec3, "lower corner [m]").magnitude(kMaxCoordinate),
    key("max", KeyType::Vec3, "upper corner, no component below min's [m]").magnitude(kMaxCoordinate),
};
inline constexpr KeyTable kRegionKeys{kRegionKeyTable, "an axis-aligned box"};

// A ragdoll's figure: what a spawn block's "ragdoll" and each of "ragdolls" take.
#define RBSIM_FIGURE_KEYS                                                                                           \
  key("orientation", KeyType::Orientation, "the figure's orientation"),                                           \
      key("scale", KeyType::Number, "size as a factor on a 1.8 m figure").within(kMinRagdollScale, kMaxRagdollScale), \
      key("mass", KeyType::Number, "the figure's mass [kg]").above(0.0).atMost(kMaxMassScale),                    \
      key("joint_friction", KeyType::Number, "friction torque of every joint [N m]").within(0.0, kMaxMassScale),  \
      key("joint_hertz", KeyType::Number, "joint spring frequency [Hz] (0: none)").within(0.0, kMaxJointHertz),   \
      key("joint_damping_ratio", KeyType::Number, "joint spring damping ratio").within(0.0, kMaxJointDampingRatio)

inline constexpr SceneKey kRagdollFigureKeyTable[] = {RBSIM_FIGURE_KEYS};
// The figure's own keys (all but name, position and velocity), as a spawn block's "ragdoll" has them.
inline constexpr KeyTable kRagdollFigureKeys{kRagdollFigureKeyTable, "a ragdoll figure to copy"};

inline constexpr SceneKey kRagdollKeyTable[] = {
    key("name", KeyType::String, "the ragdoll's name; its bones are NAME_pelvis, ... (default ragdoll<n>)"),
    key("position", KeyType::Vec3, "the pelvis's position [m]").magnitude(kMaxCoordinate),
    key("velocity", KeyType::Vec3, "every bone's velocity [m/s]").magnitude(kMaxSpeed),
    RBSIM_FIGURE_KEYS,
};
inline constexpr KeyTable kRagdollKeys{kRagdollKeyTable, "an eleven-bone ragdoll"};
#undef RBSIM_FIGURE_KEYS

// The body a spawn block copies: a body's keys but its name, pose, motion and scripts.
inline constexpr SceneKey kSpawnBodyKeyTable[] = {
    pick(kBodyKeyTable, "shape"), pick(kBodyKeyTable, "shapes"), pick(kBodyKeyTable, "mass"),
    pick(kBodyKeyTable, "density"), pick(kBodyKeyTable, "inertia"), pick(kBodyKeyTable, "orientation"),
    pick(kBodyKeyTable, "color"), pick(kBodyKeyTable, "springs"), pick(kBodyKeyTable, "restitution"),
    pick(kBodyKeyTable, "friction_static"), pick(kBodyKeyTable, "friction_kinetic"), pick(kBodyKeyTable, "fracture"),
    pick(kBodyKeyTable, "sdf"), pick(kBodyKeyTable, "filter"),
};
inline constexpr KeyTable kSpawnBodyKeys{kSpawnBodyKeyTable, "the body every copy is made from"};

inline constexpr SceneKey kSpawnKeyTable[] = {
    key("count", KeyType::Integer, "copies a burst").within(1.0, kMaxSpawnCount),
    key("seed", KeyType::Integer, "seed of the draws (default 1)").within(1.0, static_cast<double>(kMaxCount)),
    key("name", KeyType::String, "copies are named NAME_k (default spawn)"),
    key("body", KeyType::Object, "the body to copy; or ragdoll").of(kSpawnBodyKeys),
    key("ragdoll", KeyType::Object, "the ragdoll to copy; or body").of(kRagdollFigureKeys),
    key("offsets", KeyType::Vec3Array, "a copy at each offset from every drawn point [m]").magnitude(kMaxCoordinate).nonEmpty(),
    key("lifetime", KeyType::Number, "a periodic block's copies are removed after this [s]").above(0.0),
    key("region", KeyType::Object, "positions are drawn uniformly in this box").of(kRegionKeys).needed(),
    key("speed", KeyType::NumberArray, "[low, high] speed in a random direction [m/s]").sized(2).within(0.0, kMaxSpeed),
    key("angular_speed", KeyType::NumberArray, "[low, high] turning rate about a random axis [rad/s]").sized(2).atLeast(0.0),
    key("random_orientation", KeyType::Boolean, "draw each copy's orientation (default true)"),
    key("period", KeyType::Number, "time between bursts [s]; without it one burst at load").above(0.0),
    key("start", KeyType::Number, "a periodic block's first burst [s]").atLeast(0.0),
    key("end", KeyType::Number, "a periodic block's bursts stop, after start [s]"),
};
inline constexpr KeyTable kSpawnKeys{kSpawnKeyTable, "many bodies (or ragdolls) from one template, at seeded random poses"};

}  // namespace rbsim::scene_detail
