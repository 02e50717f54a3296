#include "scene/motion_ranges.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

// The angle between two orientations [rad]: 2 acos |<a, b>|, the clamp absorbing rounding.
double turnBetween(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))); }

// How fast a point of the body moves going from pose `from` to pose `to` in `seconds` [m/s].
double pathSpeed(const Keyframe& from, const Keyframe& to, double seconds, double reach) {
  return ((to.position - from.position).stableNorm() + turnBetween(from.orientation, to.orientation) * reach) / seconds;
}

}  // namespace

void checkMotionSpeeds(const JsonObject& m, const KinematicMotion& motion, const BodyDef& body, double dt) {
  double reach = 0.0;
  for (const Vec3& p : body.mesh->vertices) reach = std::max(reach, p.stableNorm());
  const auto tooFast = [&](const std::string& key, const std::string& what, double speed) {
    m.fail(key.c_str(), what + " moves the body's surface at up to " + formatNumber(speed) +
                    " m/s, faster than light (299792458 m/s); expected a slower motion");
  };
  if (motion.kind == KinematicMotion::Kind::Pivot) {
    const double speed = motion.angularVelocity.stableNorm() * ((body.position - motion.pivot).stableNorm() + reach);
    if (!(speed <= kMaxSpeed)) tooFast("angular_velocity", "turning about the pivot", speed);
    return;
  }
  Keyframe previous{0.0, body.position, body.orientation};  // where the body stands at t = 0
  for (std::size_t i = 0; i < motion.keys.size(); ++i) {
    const Keyframe& key = motion.keys[i];
    const double seconds = key.time - previous.time;
    if (seconds > 0.0) {
      const double speed = pathSpeed(previous, key, seconds, reach);
      if (!(speed <= kMaxSpeed)) {
        tooFast("keyframes[" + std::to_string(i) + "]",
                i == 0 ? std::string("coming from where it stands") : "coming from keyframes[" + std::to_string(i - 1) + "]", speed);
      }
    }
    previous = key;
  }
  if (motion.loop && motion.keys.size() >= 2) {  // the jump back to the first key, in one step
    const double speed = pathSpeed(motion.keys.back(), motion.keys.front(), dt, reach);
    if (!(speed <= kMaxSpeed)) tooFast("loop", "jumping back to keyframes[0] in one step of " + formatNumber(dt) + " s", speed);
  }
}

}  // namespace rbsim::scene_detail
