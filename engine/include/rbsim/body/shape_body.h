#pragma once
// A BodyDef from a shape and a mass, for programs that build bodies in C++ rather than from a
// scene file: the display mesh (seed 004's vertex list) tessellated from the shape, the exact
// mass properties of the shape itself (closed form for sphere, capsule and box; the polyhedral
// integrals for a hull), and the shape set, so it collides as the shape and not as its mesh.
#include <string>

#include "rbsim/body/body_def.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// Tessellation of round shapes' display meshes: fine enough that a sphere's inscribed mesh holds
// over 99 % of its volume, coarse enough that drawing and surface sampling stay cheap.
inline constexpr int kDisplaySegments = 48;  // around the axis [1]
inline constexpr int kDisplayRings = 24;     // from pole to pole [1]
// A rounded box's quarter-rounds: steps per 45 degrees, as many as a kDisplaySegments circle has.
inline constexpr int kDisplayBandSegments = kDisplaySegments / 8;  // [1]

// The display mesh of a sphere, capsule or box (throws std::invalid_argument for a hull or mesh,
// whose mesh is their own).
Mesh displayMeshOf(const Shape& shape);

// A dynamic body of `mass` [kg] with the sphere's, capsule's or box's shape at the origin, at rest.
// Throws std::invalid_argument on a mass that is not positive and finite, or a hull or mesh shape.
BodyDef shapeBodyDef(const Shape& shape, double mass, const std::string& name = "body");

}  // namespace rbsim
