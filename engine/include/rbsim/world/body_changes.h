#pragma once
// Changes of a running body's constants (PyBullet's changeDynamics; Box2D v3's b2Body_SetMassData
// and b2Shape_SetFilter; engine/src/world/body_changes.cpp), from the next step on: free functions
// over World, as every part beside the World's core is (docs/architecture.md, "The World's
// surface"). Each is checked with the scene loader's ranges and words (body/material.h,
// body/mass_ranges.h) and throws std::invalid_argument naming the call, the body, the field and
// what was expected, the World unchanged. Each wakes the body, and so at the next step its island,
// as a manual change does.
#include "rbsim/body/body_id.h"
#include "rbsim/body/material.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/collision_filter.h"

namespace rbsim {

class World;

// The mass [kg] and the inertia about the centre of mass, body frame [kg m^2]: the velocity and
// angular velocity stay, P = m v and L = I(t) omega follow (RigidBody::setMassProperties).
void setBodyMass(World& world, BodyId id, double mass, const Mat3& inertiaBody);
// Restitution and friction, read by the next step's contacts (nothing keeps the old ones). A
// compound body's materials are its shapes': refused for one, as the scene refuses them.
void setBodyMaterial(World& world, BodyId id, const Material& material);
// What the body collides with (shapes/collision_filter.h), from the next broad phase; refused
// for a compound body, whose filters are its shapes'.
void setBodyFilter(World& world, BodyId id, const CollisionFilter& filter);

}  // namespace rbsim
