#include "world/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "integrate/integrator.h"

namespace rbsim {

namespace {

bool isActive(const ScriptedForce& f, double t) { return t >= f.start && t < f.end; }

// (application point, force), both in world frame, for the body's current pose.
std::pair<Vec3, Vec3> inWorldFrame(const ScriptedForce& f, const RigidBody& body) {
  const Vec3 point = f.pointFrame == Frame::Body ? body.bodyToWorld(f.point) : f.point;
  const Vec3 force = f.forceFrame == Frame::Body ? Vec3(body.rotation() * f.force) : f.force;
  return {point, force};
}

}  // namespace

const char* stageName(Stage stage) {
  switch (stage) {
    case Stage::ApplyPoseEvents: return "apply-pose-events";
    case Stage::AccumulateForces: return "accumulate-forces";
    case Stage::Integrate: return "integrate";
    case Stage::Count: break;
  }
  return "unknown";
}

World::World(const Settings& settings) : settings_(settings) {
  const double dt = settings_.timeStep;
  if (!std::isfinite(dt) || dt <= 0.0 || dt > kMaxTimeStep) {
    throw std::invalid_argument("time step " + std::to_string(dt) + " s is outside (0, " +
                                std::to_string(kMaxTimeStep) + "] s");
  }
  if (!settings_.gravity.allFinite()) throw std::invalid_argument("gravity must be finite");
}

std::size_t World::addBody(const BodyDef& def) {
  bodies_.emplace_back(def);
  return bodies_.size() - 1;
}

void World::addForce(const ScriptedForce& force) {
  if (force.body >= bodies_.size()) throw std::invalid_argument("scripted force names no body");
  forces_.push_back(force);
}

void World::addPoseEvent(const PoseEvent& event) {
  if (event.body >= bodies_.size()) throw std::invalid_argument("pose event names no body");
  const auto at = std::upper_bound(pendingEvents_.begin(), pendingEvents_.end(), event,
                                   [](const PoseEvent& a, const PoseEvent& b) { return a.time < b.time; });
  pendingEvents_.insert(at, event);
}

template <typename Fn>
void World::runStage(Stage stage, bool needed, Fn&& fn) {
  StageStats& stats = stats_[static_cast<int>(stage)];
  if (!needed) {
    ++stats.skipped;
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  fn();
  stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++stats.runs;
}

void World::step() {
  const double t = time();
  runStage(Stage::ApplyPoseEvents, !pendingEvents_.empty() && pendingEvents_.front().time <= t,
           [&] { applyPoseEvents(); });
  runStage(Stage::AccumulateForces, !forces_.empty() || settings_.gravity != Vec3::Zero(),
           [&] { accumulateForces(); });
  runStage(Stage::Integrate, !bodies_.empty(), [&] { integrateBodies(); });
  ++stepCount_;
}

void World::applyPoseEvents() {
  const double t = time();
  auto due = pendingEvents_.begin();
  for (; due != pendingEvents_.end() && due->time <= t; ++due) {
    RigidBody& body = bodies_[due->body];
    if (due->position) body.setPosition(*due->position);
    if (due->orientation) body.setOrientation(*due->orientation);
    if (due->velocity) body.setVelocity(*due->velocity);
    if (due->angularVelocity) body.setAngularVelocity(*due->angularVelocity);
  }
  pendingEvents_.erase(pendingEvents_.begin(), due);
}

std::vector<std::pair<Vec3, Vec3>> World::activeForces(std::size_t body, double t) const {
  std::vector<std::pair<Vec3, Vec3>> active;
  const RigidBody& b = bodies_[body];
  for (const ScriptedForce& f : forces_) {
    if (f.body == body && isActive(f, t)) active.push_back(inWorldFrame(f, b));
  }
  return active;
}

void World::accumulateForces() {
  const double t = time();
  for (RigidBody& body : bodies_) body.applyForce(body.mass() * settings_.gravity);
  for (const ScriptedForce& f : forces_) {
    if (!isActive(f, t)) continue;
    RigidBody& body = bodies_[f.body];
    const auto [point, force] = inWorldFrame(f, body);
    body.applyForceAtPoint(force, point);
  }
}

void World::integrateBodies() {
  const double dt = settings_.timeStep;
  for (RigidBody& body : bodies_) {
    const StepInputs in{body.velocity(), body.angularVelocity(), body.rotation(),
                        body.force(),    body.torque(),          1.0 / body.mass(),
                        body.inertiaBody(), body.inverseInertiaBody()};
    body.setState(integrate(settings_.integrator, body.state(), in, dt));
    body.clearAccumulators();
  }
}

std::uint64_t World::stateHash() const {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
  auto mix = [&hash](double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 8; ++i) {
      hash ^= (bits >> (8 * i)) & 0xffu;
      hash *= 1099511628211ull;  // FNV-1a 64-bit prime
    }
  };
  for (const RigidBody& body : bodies_) {
    const BodyState& s = body.state();
    for (int i = 0; i < 3; ++i) mix(s.position[i]);
    for (int i = 0; i < 4; ++i) mix(s.orientation.coeffs()[i]);
    for (int i = 0; i < 3; ++i) mix(s.linearMomentum[i]);
    for (int i = 0; i < 3; ++i) mix(s.angularMomentum[i]);
  }
  return hash;
}

}  // namespace rbsim
