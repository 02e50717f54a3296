// Changes of a running body or joint in scene keys (rbsim/scene/changes.h): the body block's and
// the joint block's own readers (parseMaterial, parseFilter, parseMotor, parseLimits) over the
// values the body or joint has now.
#include "rbsim/scene/changes.h"

#include "rbsim/body/mass_ranges.h"
#include "rbsim/dynamics/joint_ranges.h"
#include "rbsim/scene/json_fields.h"
#include "scene/body_parser.h"
#include "scene/compound_parser.h"
#include "scene/joint_parser.h"

namespace rbsim {

namespace {

// "inertia": [[Ixx, Ixy, Ixz], [..], [..]] or [Ixx, Iyy, Izz] [kg m^2].
Mat3 parseInertia(const JsonObject& o) {
  const nlohmann::json& v = o.raw("inertia");
  const char* expected = "expected a 3 x 3 tensor [[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]] or its diagonal "
                         "[Ixx, Iyy, Izz] in kg m^2 (about the centre of mass, body frame)";
  if (!v.is_array() || v.size() != 3) o.fail("inertia", expected);
  Mat3 inertia = Mat3::Zero();
  for (int r = 0; r < 3; ++r) {
    const nlohmann::json& row = v[static_cast<std::size_t>(r)];
    if (row.is_number()) {
      inertia(r, r) = row.get<double>();
    } else if (row.is_array() && row.size() == 3 && row[0].is_number() && row[1].is_number() && row[2].is_number()) {
      for (int c = 0; c < 3; ++c) inertia(r, c) = row[static_cast<std::size_t>(c)].get<double>();
    } else {
      o.fail("inertia", expected);
    }
  }
  if (v[0].is_number() != v[1].is_number() || v[0].is_number() != v[2].is_number()) o.fail("inertia", expected);
  if (const std::string problem = inertiaProblem(inertia); !problem.empty()) o.fail("inertia", problem);
  return inertia;
}

}  // namespace

BodyChange parseBodyChange(const nlohmann::json& change, const std::string& file, const RigidBody& body,
                           const Material& material) {
  const JsonObject o(change, file, "", kBodyChangeKeys);
  BodyChange out;
  if (o.has("mass") || o.has("inertia")) {
    const double mass = o.positiveNumber("mass", body.mass());
    out.inertiaGiven = o.has("inertia");
    const Mat3 inertia = out.inertiaGiven ? parseInertia(o) : Mat3(body.inertiaBody() * (mass / body.mass()));
    if (const std::string problem = massScaleProblem(mass, inertia); !problem.empty()) o.fail(o.has("mass") ? "mass" : "inertia", problem);
    out.mass = mass;
    out.inertia = inertia;
  }
  const bool materialKeys = o.has("restitution") || o.has("friction_static") || o.has("friction_kinetic");
  if (materialKeys && body.isCompound()) {
    o.fail(o.has("restitution") ? "restitution" : o.has("friction_static") ? "friction_static" : "friction_kinetic",
           "a compound body's materials are its shapes'; expected the key in each");
  }
  if (materialKeys) out.material = scene_detail::parseMaterial(o, material);
  if (o.has("filter")) {
    if (body.isCompound()) o.fail("filter", "a compound body's filters are its shapes'; expected \"filter\" in each");
    out.filter = scene_detail::parseFilter(o, body.filter());
  }
  return out;
}

JointChange parseJointChange(const nlohmann::json& change, const std::string& file, const Joint& joint) {
  const JsonObject o(change, file, "", kJointChangeKeys);
  JointChange out{joint.def};
  using Type = JointDef::Type;
  const Type type = joint.def.type;
  if (o.has("motor")) {
    if (type != Type::Hinge && type != Type::Prismatic) o.fail("motor", "only a hinge or a prismatic joint takes a motor");
    out.motor = true;
    if (o.raw("motor") == false) {
      out.def.motor = false;
    } else {
      scene_detail::parseMotor(o, out.def);
    }
  }
  const char* key = limitsKey(type);
  const char* other = type == Type::Ball ? "limits" : "twist";
  if (o.has(other)) o.fail(other, type == Type::Ball ? "a ball joint's limits are its \"twist\"" : "only a ball joint takes a twist; expected \"limits\"");
  if (o.has(key)) {
    if (type == Type::Weld) o.fail(key, "a weld joint takes no limits");
    out.limits = true;
    if (o.raw(key) == false) {
      out.def.limits = false;
    } else {
      scene_detail::parseLimits(o, out.def);
    }
  }
  return out;
}

}  // namespace rbsim
