// Changes of a running body's constants (world/body_changes.h: setBodyMass, setBodyMaterial, setBodyFilter;
// PyBullet's changeDynamics, Box2D v3's b2Body_SetMassData and b2Shape_SetFilter). Each checks
// everything before it changes anything, with the scene loader's checks, and wakes the body.
#include <stdexcept>
#include <string>

#include "rbsim/body/mass_ranges.h"
#include "rbsim/world/body_changes.h"

#include "world/world_access.h"

namespace rbsim {

namespace {

// "setBodyMass: body 'ball': mass: expected ..." when problem is not empty.
void refuse(const char* call, const RigidBody& body, const char* field, const std::string& problem) {
  if (!problem.empty()) throw std::invalid_argument(std::string(call) + ": body '" + body.name() + "': " + field + ": " + problem);
}

}  // namespace

void setBodyMass(World& world, BodyId id, double mass, const Mat3& inertiaBody) {
  constexpr const char* kCall = "setBodyMass";
  RigidBody& b = WorldAccess::bodies(world)[world.indexOf(id)];
  refuse(kCall, b, "mass", massProblem(mass));
  refuse(kCall, b, "inertia", inertiaProblem(inertiaBody));
  refuse(kCall, b, "mass", massScaleProblem(mass, inertiaBody));
  b.setMassProperties(mass, inertiaBody);  // wakes it
}

void setBodyMaterial(World& world, BodyId id, const Material& material) {
  constexpr const char* kCall = "setBodyMaterial";
  const std::size_t i = world.indexOf(id);
  RigidBody& b = WorldAccess::bodies(world)[i];
  if (b.isCompound()) refuse(kCall, b, "restitution", "a compound body's materials are its shapes'; expected the key in each");
  refuse(kCall, b, "restitution", restitutionProblem(material.restitution));
  refuse(kCall, b, "friction_static", frictionProblem(material.staticFriction, "(mu_s)"));
  refuse(kCall, b, "friction_kinetic", frictionProblem(material.kineticFriction, "(mu_k)"));
  refuse(kCall, b, "friction_kinetic", frictionOrderProblem(material));
  // The solvers combine the pair's materials afresh for every contact of every step
  // (contactMaterial in dynamics/contact_solver.h), so no contact keeps the old values.
  WorldAccess::bodyMaterials(world)[i] = material;
  WorldAccess::wakeBody(world, i);
}

void setBodyFilter(World& world, BodyId id, const CollisionFilter& filter) {
  constexpr const char* kCall = "setBodyFilter";
  RigidBody& b = WorldAccess::bodies(world)[world.indexOf(id)];
  if (b.isCompound()) refuse(kCall, b, "filter", "a compound body's filters are its shapes'; expected \"filter\" in each");
  // The broad phase tests each candidate pair's filters at every step (CollisionPipeline), so the
  // next narrow phase makes no contact the new filter refuses; the joints' pairs stay ignored.
  b.setFilter(filter);  // wakes it
  ++WorldAccess::geometryVersion(world);  // the query tree keeps each body's filter (query_tree.h)
}

}  // namespace rbsim
