// The "joints" array of a scene (dynamics/joint.h): a ball, hinge, prismatic or weld joint per
// entry, each naming its bodies, its world anchor at t = 0 and, by type, its axis, motor, limits,
// cone, twist, spring, friction or weld softness (docs/scene-format.md, "Joints").
#include "scene/joint_parser.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "rbsim/math/types.h"
#include "rbsim/world/made_names.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

std::size_t bodyNamed(const JsonObject& j, const char* key, const JointBodies& bodies) {
  const std::string name = j.requiredString(key);
  if (bodies.first.empty()) {
    for (std::size_t i = bodies.names.size(); i-- > 0;) bodies.first[bodies.names[i]] = i;
  }
  if (const auto it = bodies.first.find(name); it != bodies.first.end()) return it->second;
  for (const std::string& ragdoll : bodies.ragdolls) {
    const auto bones = ragdollBodyNames(ragdoll);
    if (std::find(bones.begin(), bones.end(), name) != bones.end()) {
      j.fail(key, "no body is named \"" + name + "\": the bones of ragdoll \"" + ragdoll +
                      "\" are made when the World is built, and a scene's joints connect only its listed bodies");
    }
  }
  j.fail(key, "no body is named \"" + name + "\"");
}

// [lower, upper] of `key`, checked for the joint's type (limitsProblem).
std::pair<double, double> parseRange(const JsonObject& j, const char* key, JointDef::Type type) {
  const nlohmann::json& r = j.raw(key);
  const bool numbers = r.is_array() && r.size() == 2 && r[0].is_number() && r[1].is_number();
  if (!numbers) j.fail(key, limitsExpectation(type));
  const double lo = r[0].get<double>(), hi = r[1].get<double>();
  if (const std::string problem = limitsProblem(lo, hi, type); !problem.empty()) j.fail(key, problem);
  return {lo, hi};
}

void parseCone(const JsonObject& j, JointDef& def) {
  const nlohmann::json& c = j.raw("cone");
  if (!c.is_number() || !(c.get<double>() >= 0.0 && c.get<double>() <= kPi)) {
    j.fail("cone", "expected the cone's half-angle in radians, from 0 to pi");
  }
  def.coneLimit = true;
  def.coneAngle = c.get<double>();
}

double boundedNumber(const JsonObject& j, const char* key, double fallback, double bound, const char* unit) {
  const double x = j.number(key, fallback);
  if (!(x >= 0.0 && x <= bound)) j.fail(key, "expected a number from 0 to " + formatNumber(bound) + unit + ", got " + formatNumber(x));
  return x;
}

void parseSpring(const JsonObject& j, JointDef& def) {
  const JsonObject s = j.object("spring", kJointSpringKeys);
  if (!s.has("hertz")) s.fail("hertz", "missing; the spring's natural frequency in Hz (> 0) is required");
  def.spring = true;
  def.springHertz = boundedNumber(s, "hertz", 0.0, kMaxJointHertz, " Hz");
  if (!(def.springHertz > 0.0)) s.fail("hertz", "expected a frequency > 0 Hz; leave the spring out for none");
  def.springDampingRatio = boundedNumber(s, "damping_ratio", 0.0, kMaxJointDampingRatio, "");
}

}  // namespace

void parseMotor(const JsonObject& j, JointDef& def) {
  const bool slider = def.type == JointDef::Type::Prismatic;
  const char* maxKey = maxMotorKey(def.type);
  const JsonObject m = slider ? j.object("motor", kSliderMotorKeys) : j.object("motor", kHingeMotorKeys);
  double& max = slider ? def.maxMotorForce : def.maxMotorTorque;
  if (!def.motor) {  // a new motor states both
    if (!m.has("speed")) m.fail("speed", slider ? "missing; the motor's target speed in m/s is required" : "missing; the motor's target speed in rad/s is required");
    if (!m.has(maxKey)) {
      m.fail(maxKey, slider ? "missing; the motor's largest force in N (>= 0) is required" : "missing; the motor's largest torque in N m (>= 0) is required");
    }
  }
  const double speed = m.number("speed", def.motorSpeed);
  if (const std::string problem = motorSpeedProblem(speed, def.type); !problem.empty()) m.fail("speed", problem);
  const double largest = m.number(maxKey, max);
  if (const std::string problem = maxMotorProblem(largest, def.type); !problem.empty()) m.fail(maxKey, problem);
  def.motor = true;
  def.motorSpeed = speed;
  max = largest;
}

void parseLimits(const JsonObject& j, JointDef& def) {
  const char* key = limitsKey(def.type);
  const auto [lo, hi] = parseRange(j, key, def.type);
  def.limits = true;
  (def.type == JointDef::Type::Prismatic ? def.lowerTranslation : def.lowerAngle) = lo;
  (def.type == JointDef::Type::Prismatic ? def.upperTranslation : def.upperAngle) = hi;
}

JointDef parseJoint(const JsonObject& j, const JointBodies& bodies, const Settings& settings) {
  using Type = JointDef::Type;
  JointDef def;
  const std::string type = j.requiredString("type");
  if (type == "ball") {
    def.type = Type::Ball;
    j.allowOnly(kBallJointKeys, "a \"ball\" joint");
  } else if (type == "hinge") {
    def.type = Type::Hinge;
    j.allowOnly(kHingeJointKeys, "a \"hinge\" joint");
  } else if (type == "prismatic") {
    def.type = Type::Prismatic;
    j.allowOnly(kPrismaticJointKeys, "a \"prismatic\" joint");
  } else if (type == "weld") {
    def.type = Type::Weld;
    j.allowOnly(kWeldJointKeys, "a \"weld\" joint");
  } else {
    j.fail("type", "expected \"ball\", \"hinge\", \"prismatic\" or \"weld\", got \"" + type + "\"");
  }
  def.name = j.string("name", "");
  if (settings.solver != Settings::ContactSolverMethod::SoftStep) {
    const std::string which = settings.solver == Settings::ContactSolverMethod::Pgs ? "PGS" : "LCP";
    j.fail("type", "joints need world.solver \"soft-step\"; the " + which + " solver does not solve joints");
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
  // A hinge and a slider need their axis; a ball needs one only for its cone or twist.
  const bool needsAxis = def.type == Type::Hinge || def.type == Type::Prismatic || j.has("cone") || j.has("twist");
  if (needsAxis || j.has("axis")) {
    if (!j.has("axis")) {
      j.fail("axis", def.type == Type::Ball ? "missing; a ball joint's cone or twist needs its axis (world frame at t = 0)"
                                            : "missing; the joint's axis (world frame at t = 0) is required");
    }
    const Vec3 axis = j.vec3("axis", Vec3::UnitZ());
    const double length = axis.stableNorm();
    if (!(length > 0.0) || !std::isfinite(length)) j.fail("axis", "expected a non-zero direction");
    def.axis = axis / length;
  }
  if (j.has("motor")) parseMotor(j, def);
  if (j.has(limitsKey(def.type))) parseLimits(j, def);
  if (j.has("cone")) parseCone(j, def);
  if (j.has("spring")) parseSpring(j, def);
  def.friction = boundedNumber(j, "friction", 0.0, kMaxJointFriction, def.type == Type::Prismatic ? " N" : " N m");
  def.linearHertz = boundedNumber(j, "linear_hertz", 0.0, kMaxJointHertz, " Hz");
  def.linearDampingRatio = boundedNumber(j, "linear_damping_ratio", 0.0, kMaxJointDampingRatio, "");
  def.angularHertz = boundedNumber(j, "angular_hertz", 0.0, kMaxJointHertz, " Hz");
  def.angularDampingRatio = boundedNumber(j, "angular_damping_ratio", 0.0, kMaxJointDampingRatio, "");
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
  for (const RagdollDef& r : scene.ragdolls) bodies.ragdolls.push_back(r.name);
  for (const JsonObject& j : root.objectArray("joints", kJointKeys)) scene.joints.push_back(parseJoint(j, bodies, scene.settings));
}

}  // namespace rbsim::scene_detail
