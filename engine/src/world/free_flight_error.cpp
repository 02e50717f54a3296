#include "rbsim/world/free_flight_error.h"

#include <algorithm>

#include "rbsim/world/queries.h"

namespace rbsim {

namespace {

double spinEnergy(const RigidBody& body) { return 0.5 * body.state().angularMomentum.dot(body.angularVelocity()); }

// Whether anything but the integrator turned the body during the step that ended at world.time():
// a contact (the speculative ones within the margin included), a spring, a joint, or a scripted
// force with a moment about the centre of mass.
bool torqued(const World& world, BodyId id) {
  const std::size_t i = world.indexOf(id);
  for (const Contact& c : world.contacts()) {
    if (c.b == i || (c.kind == Contact::Kind::BodyBody && c.a == i)) return true;
  }
  for (const Spring& s : springs(world)) {
    if (s.body == id) return true;
  }
  for (const Joint& j : world.joints()) {
    if (j.def.bodyA == id || j.def.bodyB == id) return true;
  }
  const RigidBody& body = world.bodies()[i];
  const double stepStart = world.time() - world.settings().timeStep;
  for (double t : {stepStart, world.time()}) {
    for (const auto& [point, force] : activeForces(world, id, t)) {
      if (!(point - body.position()).cross(force).isZero(0.0)) return true;
    }
  }
  return false;
}

}  // namespace

void FreeFlightError::observe(const World& world) {
  if (!world.isValid(body_)) {
    flow_.reset();
    return;
  }
  const RigidBody& body = world.body(body_);
  if (!body.isDynamic() || !body.awake()) {
    flow_.reset();
    return;
  }
  if (flow_ && !torqued(world, body_)) return;
  const Quat principalToBody(body.principalAxes());
  bodyToPrincipal_ = principalToBody.conjugate();
  flow_.emplace(body.orientation() * principalToBody, body.state().angularMomentum, body.principalMoments());
  epochTime_ = world.time();
  spinEnergy_ = spinEnergy(body);
}

FreeFlightError::Reading FreeFlightError::read(const World& world) const {
  Reading r;
  if (!flow_ || !world.isValid(body_)) return r;
  const RigidBody& body = world.body(body_);
  r.tracked = true;
  r.since = epochTime_;
  const Quat exact = flow_->principalToWorld(world.time() - epochTime_) * bodyToPrincipal_;
  r.angle = exact.angularDistance(body.orientation());
  r.energy = spinEnergy_ > 0.0 ? spinEnergy(body) / spinEnergy_ - 1.0 : 0.0;
  return r;
}

}  // namespace rbsim
