// The "joints" array of a scene (dynamics/joint.h): a ball or hinge joint per entry, each naming
// its bodies, its world anchor at t = 0 and, for a hinge, its axis, motor and limits.
#include "scene/joint_parser.h"

#include <cmath>

#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

std::size_t bodyNamed(const JsonObject& j, const char* key, const JointBodies& bodies) {
  const std::string name = j.requiredString(key);
  if (bodies.first.empty()) {
    for (std::size_t i = bodies.names.size(); i-- > 0;) bodies.first[bodies.names[i]] = i;
  }
  if (const auto it = bodies.first.find(name); it != bodies.first.end()) return it->second;
  j.fail(key, "no body is named \"" + name + "\"");
}

void parseMotor(const JsonObject& j, JointDef& def) {
  const JsonObject m = j.object("motor", {"speed", "max_torque"});
  def.motor = true;
  if (!m.has("speed")) m.fail("speed", "missing; the motor's target speed in rad/s is required");
  if (!m.has("max_torque")) m.fail("max_torque", "missing; the motor's largest torque in N m (>= 0) is required");
  def.motorSpeed = m.requiredNumber("speed");
  def.maxMotorTorque = m.requiredNumber("max_torque");
  if (!(std::abs(def.motorSpeed) <= kMaxMotorSpeed)) {
    m.fail("speed", "expected a speed of at most " + formatNumber(kMaxMotorSpeed) + " rad/s either way, got " + formatNumber(def.motorSpeed));
  }
  if (!(def.maxMotorTorque >= 0.0 && def.maxMotorTorque <= kMaxMotorTorque)) {
    m.fail("max_torque", "expected a torque from 0 to " + formatNumber(kMaxMotorTorque) + " N m, got " + formatNumber(def.maxMotorTorque));
  }
}

void parseLimits(const JsonObject& j, JointDef& def) {
  const nlohmann::json& r = j.raw("limits");
  const bool numbers = r.is_array() && r.size() == 2 && r[0].is_number() && r[1].is_number();
  const double lo = numbers ? r[0].get<double>() : 0.0, hi = numbers ? r[1].get<double>() : 0.0;
  if (!numbers || !(lo >= -M_PI && lo <= hi && hi <= M_PI)) {
    j.fail("limits", "expected [lower, upper] angles in radians with -pi <= lower <= upper <= pi");
  }
  def.limits = true;
  def.lowerAngle = lo;
  def.upperAngle = hi;
}

}  // namespace

JointDef parseJoint(const JsonObject& j, const JointBodies& bodies, const Settings& settings) {
  JointDef def;
  const std::string type = j.requiredString("type");
  if (type == "ball") {
    def.type = JointDef::Type::Ball;
    j.allowOnly({"name", "type", "body_a", "body_b", "anchor", "collide_connected"}, "a \"ball\" joint");
  } else if (type == "hinge") {
    def.type = JointDef::Type::Hinge;
  } else {
    j.fail("type", "expected \"ball\" or \"hinge\", got \"" + type + "\"");
  }
  def.name = j.string("name", "");
  if (settings.solver == Settings::ContactSolverMethod::Pgs) {
    j.fail("type", "joints need world.solver \"soft-step\"; the PGS solver does not solve joints");
  }
  const std::size_t a = bodyNamed(j, "body_a", bodies);
  def.bodyA = bodies.ids[a];
  if (!bodies.dynamic[a]) {
    j.fail("body_a", "\"" + bodies.names[a] + "\" is static or kinematic; expected a dynamic body (body_b may be any body)");
  }
  if (j.has("body_b")) {
    def.bodyB = bodies.ids[bodyNamed(j, "body_b", bodies)];
    if (def.bodyB == def.bodyA) j.fail("body_b", "names body_a again; expected another body, or no body_b for the world");
  }
  if (!j.has("anchor")) j.fail("anchor", "missing; the joint's world point at t = 0 in m is required");
  def.anchor = j.boundedVec3("anchor", Vec3::Zero(), kMaxCoordinate, "m", "the largest coordinate a scene may use");
  if (def.type == JointDef::Type::Hinge) {
    if (!j.has("axis")) j.fail("axis", "missing; a hinge's axis (world frame at t = 0) is required");
    const Vec3 axis = j.vec3("axis", Vec3::UnitZ());
    const double length = axis.stableNorm();
    if (!(length > 0.0) || !std::isfinite(length)) j.fail("axis", "expected a non-zero direction");
    def.axis = axis / length;
    if (j.has("motor")) parseMotor(j, def);
    if (j.has("limits")) parseLimits(j, def);
  }
  def.collideConnected = j.boolean("collide_connected", false);
  return def;
}

void parseJoints(const JsonObject& root, Scene& scene) {
  if (root.has("joints") && root.raw("joints").is_array() && root.raw("joints").size() > kMaxJoints) {
    root.fail("joints", std::to_string(root.raw("joints").size()) + " joints; the limit is " + std::to_string(kMaxJoints));
  }
  JointBodies bodies;
  for (const BodyDef& b : scene.bodies) {
    bodies.names.push_back(b.name);
    bodies.dynamic.push_back(!b.isStatic && !b.isKinematic);
    bodies.ids.push_back(sceneBodyId(bodies.ids.size()));
  }
  for (const JsonObject& j : root.objectArray("joints", kJointKeys)) scene.joints.push_back(parseJoint(j, bodies, scene.settings));
}

}  // namespace rbsim::scene_detail
