#pragma once
// The keys of a body block, its shape (by type) and what hangs on it, and of a plane
// (rbsim/scene/scene_keys.h): names, types, ranges and a line each. body_parser.cpp,
// compound_parser.cpp and fracture_parser.cpp read them.
#include <cstdint>
#include <limits>

#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/scene/scene_keys.h"
#include "rbsim/scene/world_keys.h"
#include "scene/fracture_parser.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

inline constexpr const char* kFrameNames[] = {"body", "world"};
inline constexpr const char* kTrianglesName[] = {"triangles"};
inline constexpr const char* kPartTypeNames[] = {"box", "sphere", "capsule", "rounded_box", "hull"};

// Restitution and frictions, of a body, a compound's shape or a plane.
#define RBSIM_MATERIAL_KEYS                                                                                              \
  key("restitution", KeyType::Number, "coefficient of restitution c_R (a pair takes the larger)").within(0.0, 1.0),    \
      key("friction_static", KeyType::Number, "static friction mu_s (a pair takes the geometric mean)").atLeast(0.0), \
      key("friction_kinetic", KeyType::Number, "kinetic friction mu_k, at most mu_s").atLeast(0.0)

inline constexpr SceneKey kShapeKeyTable[] = {
    key("type", KeyType::String, "the shape's kind").needed(),
    key("extents", KeyType::Vec3, "full size along x, y, z [m]"),
    key("file", KeyType::String, "OBJ file, relative to the scene file"),
    key("scale", KeyType::Number, "factor on the mesh's coordinates"),
    key("radius", KeyType::Number, "radius [m]"),
    key("major_radius", KeyType::Number, "ring radius [m]"),
    key("minor_radius", KeyType::Number, "tube radius [m]"),
    key("thickness", KeyType::Number, "shell thickness [m]"),
    key("stroke", KeyType::Number, "stroke width [m]"),
    key("length", KeyType::Number, "distance between the caps' centres [m]"),
    key("function", KeyType::String, "an implicit shape's function"),
    key("op", KeyType::String, "a csg shape's operation"),
    key("a", KeyType::Object, "a csg shape's first operand (an implicit or csg shape)"),
    key("b", KeyType::Object, "a csg shape's second operand (an implicit or csg shape)"),
    key("position", KeyType::Vec3, "an implicit shape's position in the body [m]"),
    key("orientation", KeyType::Orientation, "an implicit shape's orientation in the body"),
    key("resolution", KeyType::Integer, "an implicit shape's grid cells along its longest side"),
    key("radii", KeyType::Vec3, "an ellipsoid's semi-axes [m]"),
    key("height", KeyType::Number, "a cylinder's or cone's height [m]"),
};
inline constexpr KeyTable kShapeKeys{kShapeKeyTable, "a body's shape, its keys by \"type\""};

inline constexpr SceneKey kBoxKeyTable[] = {
    key("type", KeyType::String, "\"box\""), key("extents", KeyType::Vec3, "full size along x, y, z [m]").above(0.0).needed()};
inline constexpr SceneKey kSphereKeyTable[] = {
    key("type", KeyType::String, "\"sphere\""), key("radius", KeyType::Number, "radius [m] (default 0.5)").above(0.0)};
inline constexpr SceneKey kCapsuleKeyTable[] = {
    key("type", KeyType::String, "\"capsule\""), key("radius", KeyType::Number, "radius [m] (default 0.25)").above(0.0),
    key("length", KeyType::Number, "distance between the caps' centres along y [m] (default 1)").atLeast(0.0)};
inline constexpr SceneKey kRoundedBoxKeyTable[] = {
    key("type", KeyType::String, "\"rounded_box\""), key("extents", KeyType::Vec3, "the outer box [m]").above(0.0).needed(),
    key("radius", KeyType::Number, "rounding radius, at most half the smallest extent [m]").above(0.0)};
inline constexpr SceneKey kTorusKeyTable[] = {
    key("type", KeyType::String, "\"torus\""), key("major_radius", KeyType::Number, "ring radius [m] (default 0.5)").above(0.0),
    key("minor_radius", KeyType::Number, "tube radius, below major_radius [m] (default 0.15)").above(0.0)};
inline constexpr SceneKey kBowlKeyTable[] = {
    key("type", KeyType::String, "\"bowl\""), key("radius", KeyType::Number, "outer radius [m] (default 1)").above(0.0),
    key("thickness", KeyType::Number, "shell thickness, below radius [m] (default 0.1)").above(0.0)};
inline constexpr SceneKey kLetterUKeyTable[] = {
    key("type", KeyType::String, "\"letter_u\""), key("extents", KeyType::Vec3, "width, height, depth [m]").above(0.0).needed(),
    key("stroke", KeyType::Number, "stroke width, below half the width and the height [m]").above(0.0)};
inline constexpr SceneKey kMeshKeyTable[] = {
    key("type", KeyType::String, "\"mesh\""), key("file", KeyType::String, "OBJ file, relative to the scene file").needed(),
    key("scale", KeyType::Number, "factor on the mesh's coordinates (default 1)").above(0.0)};
inline constexpr const char* kImplicitFunctionNames[] = {"sphere", "ellipsoid", "torus", "box", "capsule", "cylinder"};
inline constexpr const char* kCsgOperationNames[] = {"union", "intersection", "difference"};
inline constexpr SceneKey kImplicitKeyTable[] = {
    key("type", KeyType::String, "\"implicit\""), key("function", KeyType::String, "the function's kind").oneOf(kImplicitFunctionNames).needed(),
    key("radius", KeyType::Number, "radius [m]").above(0.0).atMost(kMaxCoordinate),
    key("radii", KeyType::Vec3, "an ellipsoid's semi-axes [m]").above(0.0).atMost(kMaxCoordinate),
    key("major_radius", KeyType::Number, "ring radius [m]").above(0.0).atMost(kMaxCoordinate),
    key("minor_radius", KeyType::Number, "tube radius, below major_radius [m]").above(0.0).atMost(kMaxCoordinate),
    key("extents", KeyType::Vec3, "full size [m]").above(0.0).atMost(kMaxCoordinate),
    key("length", KeyType::Number, "a capsule's distance between the caps' centres [m]").within(0.0, kMaxCoordinate),
    key("height", KeyType::Number, "a cylinder's height [m]").above(0.0).atMost(kMaxCoordinate),
    key("position", KeyType::Vec3, "position in the body [m]").magnitude(kMaxCoordinate),
    key("orientation", KeyType::Orientation, "orientation in the body"),
    key("resolution", KeyType::Integer, "grid cells along the longest side").within(kMinSdfResolution, kMaxSdfResolution)};
inline constexpr SceneKey kCsgKeyTable[] = {
    key("type", KeyType::String, "\"csg\""), key("op", KeyType::String, "the operation on a and b").oneOf(kCsgOperationNames).needed(),
    key("a", KeyType::Object, "first operand (an implicit or csg shape)").needed(),
    key("b", KeyType::Object, "second operand (an implicit or csg shape)").needed(),
    key("position", KeyType::Vec3, "position in the body [m]"), key("orientation", KeyType::Orientation, "orientation in the body"),
    key("resolution", KeyType::Integer, "grid cells along the longest side").within(kMinSdfResolution, kMaxSdfResolution)};

inline constexpr KeyTable kBoxKeys{kBoxKeyTable}, kSphereKeys{kSphereKeyTable}, kCapsuleKeys{kCapsuleKeyTable},
    kRoundedBoxKeys{kRoundedBoxKeyTable}, kTorusKeys{kTorusKeyTable}, kBowlKeys{kBowlKeyTable}, kLetterUKeys{kLetterUKeyTable},
    kMeshKeys{kMeshKeyTable}, kImplicitKeys{kImplicitKeyTable}, kCsgKeys{kCsgKeyTable};
inline constexpr KeyVariant kShapeVariants[] = {
    {"box", &kBoxKeys, "a box"},
    {"sphere", &kSphereKeys, "a sphere"},
    {"capsule", &kCapsuleKeys, "two hemispheres joined by a cylinder along y"},
    {"rounded_box", &kRoundedBoxKeys, "a box with rounded edges and corners"},
    {"torus", &kTorusKeys, "a torus about y"},
    {"bowl", &kBowlKeys, "a hemispherical shell opening up"},
    {"letter_u", &kLetterUKeys, "the letter U"},
    {"mesh", &kMeshKeys, "an OBJ mesh"},
    {"implicit", &kImplicitKeys, "a shape given by a signed distance function"},
    {"csg", &kCsgKeys, "a union, intersection or difference of two shapes"},
};

inline constexpr SceneKey kForceKeyTable[] = {
    key("force", KeyType::Vec3, "the force [N]"),
    key("point", KeyType::Vec3, "where it acts [m]"),
    key("force_frame", KeyType::String, "frame of force (default world)").oneOf(kFrameNames),
    key("point_frame", KeyType::String, "frame of point (default body: it moves with the body)").oneOf(kFrameNames),
    key("start", KeyType::Number, "when it starts acting [s]").atLeast(0.0),
    key("end", KeyType::Number, "when it stops, after start [s] (default: the scene's end)"),
};
inline constexpr KeyTable kForceKeys{kForceKeyTable, "a force acting for start <= t < end"};

inline constexpr SceneKey kSetPoseKeyTable[] = {
    key("time", KeyType::Number, "when [s]").atLeast(0.0).needed(),
    key("position", KeyType::Vec3, "centre of mass [m]").magnitude(kMaxCoordinate),
    key("orientation", KeyType::Orientation, "orientation of the file's axes"),
    key("velocity", KeyType::Vec3, "velocity [m/s]").magnitude(kMaxSpeed),
    key("angular_velocity", KeyType::Vec3, "angular velocity [rad/s]"),
};
inline constexpr KeyTable kSetPoseKeys{kSetPoseKeyTable, "a pose set by hand at a time"};

inline constexpr SceneKey kSpringKeyTable[] = {
    key("anchor", KeyType::Vec3, "fixed world point [m]").magnitude(kMaxCoordinate),
    key("point", KeyType::Vec3, "point on the body, in the file's axes about the centre of mass [m]"),
    key("stiffness", KeyType::Number, "k [N/m] (default 1)").above(0.0),
    key("rest_length", KeyType::Number, "l0 [m]").atLeast(0.0),
    key("damping", KeyType::Number, "c [N s/m]").atLeast(0.0),
};
inline constexpr KeyTable kSpringKeys{kSpringKeyTable, "a spring from a world anchor to a point of the body"};

inline constexpr SceneKey kCutPlaneKeyTable[] = {
    key("normal", KeyType::Vec3, "the plane's normal, non-zero"),
    key("point", KeyType::Vec3, "a point of the plane, about the centre of mass [m]"),
};
inline constexpr KeyTable kCutPlaneKeys{kCutPlaneKeyTable, "a cutting plane"};

inline constexpr SceneKey kFractureKeyTable[] = {
    key("threshold", KeyType::Number, "breaking impulse [N s]").above(0.0).needed(),
    key("pieces", KeyType::Integer, "Voronoi pieces (default 8)").within(2.0, kMaxFracturePieces),
    key("seed", KeyType::Integer, "seed of the Voronoi sites").within(1.0, static_cast<double>(kMaxCount)),
    key("planes", KeyType::ObjectArray, "cut by these planes instead of Voronoi pieces").of(kCutPlaneKeys),
};
inline constexpr KeyTable kFractureKeys{kFractureKeyTable, "the body breaks into pieces under a large impulse"};

inline constexpr SceneKey kSdfKeyTable[] = {
    key("resolution", KeyType::Integer, "grid cells along the longest side").within(kMinSdfResolution, kMaxSdfResolution),
    key("sample_spacing", KeyType::Number, "surface sample spacing [m] (0: the vertices only)").atLeast(0.0),
};
inline constexpr KeyTable kSdfKeys{kSdfKeyTable, "a signed distance grid for the body"};

inline constexpr SceneKey kFilterKeyTable[] = {
    key("category", KeyType::Integer, "the shape's category bits").within(0.0, static_cast<double>(std::numeric_limits<std::uint64_t>::max())),
    key("mask", KeyType::Integer, "the categories it collides with").within(0.0, static_cast<double>(std::numeric_limits<std::uint64_t>::max())),
    key("group", KeyType::Integer, "same positive group: always collide; same negative: never (0: none)")
        .within(std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()),
};
inline constexpr KeyTable kFilterKeys{kFilterKeyTable, "which shapes collide"};

inline constexpr SceneKey kKeyframeKeyTable[] = {
    key("time", KeyType::Number, "when [s]").atLeast(0.0).needed(),
    key("position", KeyType::Vec3, "centre of mass [m]").magnitude(kMaxCoordinate),
    key("orientation", KeyType::Orientation, "orientation of the file's axes"),
};
inline constexpr KeyTable kKeyframeKeys{kKeyframeKeyTable, "a pose the body passes through"};

inline constexpr SceneKey kMotionKeyTable[] = {
    key("pivot", KeyType::Vec3, "point the body turns about [m]").magnitude(kMaxCoordinate),
    key("angular_velocity", KeyType::Vec3, "turning rate about the pivot [rad/s]"),
    key("keyframes", KeyType::ObjectArray, "poses in time, instead of a pivot").of(kKeyframeKeys),
    key("loop", KeyType::Boolean, "repeat the keyframes"),
};
inline constexpr KeyTable kMotionKeys{kMotionKeyTable, "a kinematic body's prescribed motion"};

inline constexpr SceneKey kCompoundPartKeyTable[] = {
    key("type", KeyType::String, "the part's kind").oneOf(kPartTypeNames).needed(),
    key("extents", KeyType::Vec3, "full size [m]").above(0.0),
    key("radius", KeyType::Number, "radius [m]").above(0.0),
    key("length", KeyType::Number, "a capsule's length between the caps' centres [m]").atLeast(0.0),
    key("vertices", KeyType::Vec3Array, "a hull's points [m]"),
    key("triangles", KeyType::Any, "a hull's triangles, as vertex index triples"),
    key("position", KeyType::Vec3, "position in the body [m]").magnitude(kMaxCoordinate),
    key("orientation", KeyType::Orientation, "orientation in the body"),
    key("density", KeyType::Number, "density [kg/m^3]").above(0.0),
    RBSIM_MATERIAL_KEYS,
    key("filter", KeyType::Object, "which shapes it collides with").of(kFilterKeys),
};
inline constexpr KeyTable kCompoundPartKeys{kCompoundPartKeyTable, "one shape of a compound body"};

inline constexpr SceneKey kBodyKeyTable[] = {
    key("name", KeyType::String, "the body's name, unique (default body<index>)"),
    key("shape", KeyType::Object, "the body's shape").of(kShapeKeys).byType(kShapeVariants),
    key("mass", KeyType::Number, "mass [kg]; or density").above(0.0),
    key("density", KeyType::Number, "density [kg/m^3]; or mass").above(0.0),
    key("inertia", KeyType::String, "inertia method (default world.inertia)").oneOf(kInertiaMethodNames),
    key("position", KeyType::Vec3, "centre of mass [m]").magnitude(kMaxCoordinate),
    key("orientation", KeyType::Orientation, "orientation of the file's axes"),
    key("velocity", KeyType::Vec3, "velocity [m/s], below light's").magnitude(kMaxSpeed),
    key("angular_velocity", KeyType::Vec3, "angular velocity [rad/s]"),
    key("color", KeyType::Vec3, "linear RGB").within(0.0, 1.0),
    key("static", KeyType::Boolean, "never moves"),
    key("kinematic", KeyType::Boolean, "moves as its velocities or motion say, nothing else"),
    key("forces", KeyType::ObjectArray, "scripted forces").of(kForceKeys),
    key("set_pose", KeyType::ObjectArray, "poses set by hand").of(kSetPoseKeys),
    key("springs", KeyType::ObjectArray, "springs to world anchors").of(kSpringKeys),
    RBSIM_MATERIAL_KEYS,
    key("fracture", KeyType::Object, "break into pieces").of(kFractureKeys),
    key("sdf", KeyType::Object, "signed distance grid").of(kSdfKeys),
    key("shapes", KeyType::ObjectArray, "a compound body's shapes, instead of shape").of(kCompoundPartKeys).nonEmpty(),
    key("filter", KeyType::Object, "collision filter").of(kFilterKeys),
    key("motion", KeyType::Object, "a kinematic body's motion").of(kMotionKeys),
    key("collide_as", KeyType::String, "a static mesh ground colliding as its triangles").oneOf(kTrianglesName),
};
inline constexpr KeyTable kBodyKeys{kBodyKeyTable, "a rigid body"};

inline constexpr SceneKey kPlaneKeyTable[] = {
    key("normal", KeyType::Vec3, "the plane's normal, non-zero (default [0, 1, 0])"),
    key("point", KeyType::Vec3, "a point of the plane [m]").magnitude(kMaxCoordinate),
    RBSIM_MATERIAL_KEYS,
};
inline constexpr KeyTable kPlaneKeys{kPlaneKeyTable, "an infinite static plane"};

#undef RBSIM_MATERIAL_KEYS

}  // namespace rbsim::scene_detail
