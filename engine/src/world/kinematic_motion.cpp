// Kinematic bodies on a prescribed motion (world/kinematic_motion.h): each step, the velocity
// and angular velocity that carry the body from its pose now exactly onto the path's pose at the
// step's end, for the kinematic integration (x + v dt, exp(omega dt) q: integrate/integrator.h).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "rbsim/body/rigid_body.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/world.h"
#include "world/world_access.h"

namespace rbsim {

namespace {

std::string keyField(std::size_t k, const char* field) { return "keys[" + std::to_string(k) + "]." + field; }

// The rotation vector w with exp(w) from `from` gives `to` (the shorter way round).
Vec3 rotationBetween(const Quat& from, const Quat& to) {
  Quat delta = to * from.conjugate();
  if (delta.w() < 0.0) delta.coeffs() = -delta.coeffs();
  const Eigen::AngleAxisd turn(delta.normalized());
  return turn.angle() * turn.axis();
}

}  // namespace

std::string checkKinematicMotion(const KinematicMotion& motion) {
  if (motion.kind == KinematicMotion::Kind::Pivot) {
    if (!motion.pivot.allFinite()) return "pivot: expected a finite point [m]";
    if (!motion.angularVelocity.allFinite()) return "angular_velocity: expected a finite vector [rad/s]";
    return {};
  }
  if (motion.keys.empty()) return "keys: expected at least one keyframe";
  if (motion.keys.size() > kMaxKeyframes) {
    return "keys: " + std::to_string(motion.keys.size()) + " keyframes; expected at most " + std::to_string(kMaxKeyframes) +
           " (a key every step of 1/60 s for 27 minutes)";
  }
  for (std::size_t k = 0; k < motion.keys.size(); ++k) {
    const Keyframe& key = motion.keys[k];
    if (!std::isfinite(key.time)) return keyField(k, "time") + ": expected a finite time [s]";
    if (k > 0 && !(key.time > motion.keys[k - 1].time)) return keyField(k, "time") + ": expected a time after the previous key's";
    if (!key.position.allFinite()) return keyField(k, "position") + ": expected a finite point [m]";
    if (!(std::abs(key.orientation.norm() - 1.0) <= kRotationTolerance)) {
      return keyField(k, "orientation") + ": expected a unit quaternion";
    }
  }
  if (motion.loop && motion.keys.size() < 2) return "loop: expected at least two keyframes to repeat";
  return {};
}

Keyframe keyframePoseAt(const KinematicMotion& motion, double t) {
  const std::vector<Keyframe>& keys = motion.keys;
  const double first = keys.front().time, last = keys.back().time;
  if (motion.loop && t > last) t = first + std::fmod(t - first, last - first);
  if (t <= first) return keys.front();
  if (t >= last) return keys.back();
  // The first key at or after t (first < t < last: one after the first, and one exists).
  const auto next = std::lower_bound(keys.begin() + 1, keys.end(), t, [](const Keyframe& key, double time) { return key.time < time; });
  const Keyframe& a = *(next - 1);
  const Keyframe& b = *next;
  const double s = (t - a.time) / (b.time - a.time);
  return {t, a.position + s * (b.position - a.position), a.orientation.slerp(s, b.orientation)};
}

void setKinematicMotion(World& world, const KinematicMotion& motion) {
  const RigidBody& moved = std::as_const(world).body(motion.body);  // throws on a stale id
  if (!moved.isKinematic()) throw std::invalid_argument("motion: body '" + moved.name() + "' is not kinematic");
  const std::string problem = checkKinematicMotion(motion);
  if (!problem.empty()) throw std::invalid_argument("motion of body '" + moved.name() + "': " + problem);
  std::vector<KinematicMotion>& motions = WorldAccess::motions(world);
  for (KinematicMotion& m : motions) {
    if (m.body == motion.body) {
      m = motion;
      return;
    }
  }
  motions.push_back(motion);
}

const std::vector<KinematicMotion>& kinematicMotions(const World& world) { return WorldAccess::motions(world); }

void World::driveKinematicBodies() {
  const double t = time();
  const double dt = settings_.timeStep;
  for (const KinematicMotion& motion : motions_) {
    RigidBody& moved = body(motion.body);
    if (motion.kind == KinematicMotion::Kind::Pivot) {
      // The centre of mass on its circle about the axis: the chord over the step, so the body
      // stays on the circle however long it turns.
      const Mat3 turn = rotationFromAxisAngle(dt * motion.angularVelocity);
      const Vec3 next = motion.pivot + turn * (moved.position() - motion.pivot);
      moved.setVelocity((next - moved.position()) / dt);
      moved.setAngularVelocity(motion.angularVelocity);
      continue;
    }
    Keyframe target;
    if (t + dt < motion.keys.front().time) {
      // On the way to the first key, arriving at its time.
      const double s = dt / (motion.keys.front().time - t);
      target = {t + dt, moved.position() + s * (motion.keys.front().position - moved.position()),
                moved.orientation().slerp(s, motion.keys.front().orientation)};
    } else {
      target = keyframePoseAt(motion, t + dt);
    }
    moved.setVelocity((target.position - moved.position()) / dt);
    moved.setAngularVelocity(rotationBetween(moved.orientation(), target.orientation) / dt);
  }
}

}  // namespace rbsim
