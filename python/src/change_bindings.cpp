// Changes while running (issue 57): World.set_body, body_properties, set_joint and remove_joint,
// PyBullet's changeDynamics, getDynamicsInfo, setJointMotorControl2 and removeConstraint. The
// keywords are keys of the scene format read by the scene loader's own readers over the values
// the body or joint has now (rbsim/scene/changes.h), then handed to the World's change calls
// (setBodyMass, setBodyMaterial, setBodyFilter, setJointMotor, setJointLimits,
// removeJoint), so a refused call changes nothing and says what a scene file would.
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/changes.h"
#include "rbsim/world/body_changes.h"
#include "rbsim/world/joint_changes.h"
#include "rbsim/world/queries.h"
#include "to_json.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

constexpr const char* kSetBodyCall = "World.set_body()";
constexpr const char* kSetJointCall = "World.set_joint()";
constexpr const char* kRemoveJointCall = "World.remove_joint()";
// The inertia method a renderer names beside a body whose inertia was given by hand (Scene::inertiaMethods).
constexpr const char* kGivenInertia = "given";

// The joint's index, checked against the World's joints; InputError naming the call.
std::size_t jointArgument(const PyWorld& w, const py::handle& value, const char* call) {
  const long long j = intArgument(value, call, "joint");
  const std::size_t count = w.world().joints().size();
  if (j < 0 || static_cast<unsigned long long>(j) >= count) {
    throw InputError(call, "joint", "no joint has index " + std::to_string(j) + "; expected 0 to " +
                                        std::to_string(count) + " - 1 (the index add_joint returned; a removed "
                                        "joint's later ones moved down one)");
  }
  return static_cast<std::size_t>(j);
}

void setBody(PyWorld& w, const PyBodyId& id, const py::kwargs& keys) {
  const nlohmann::json change = toJson(givenKeywords(keys), kSetBodyCall, "");
  const std::size_t i = w.index(id, kSetBodyCall);  // waits for a step
  World& world = w.world();
  const BodyChange c = parseBodyChange(change, kSetBodyCall, world.bodies()[i], rbsim::bodyMaterial(world, id.id));
  try {  // parseBodyChange ran the World's checks: these calls take what it gives
    if (c.mass) rbsim::setBodyMass(world, id.id, *c.mass, *c.inertia);
    if (c.material) rbsim::setBodyMaterial(world, id.id, *c.material);
    if (c.filter) rbsim::setBodyFilter(world, id.id, *c.filter);
  } catch (const std::invalid_argument& e) {
    throw InputError(kSetBodyCall, "", e.what());
  }
  // The method a renderer names beside the body is no longer what made its inertia (spawned
  // bodies have none listed).
  if (c.inertiaGiven && i < w.scene().inertiaMethods.size()) w.scene().inertiaMethods[i] = kGivenInertia;
}

py::dict bodyProperties(const PyWorld& w, const PyBodyId& id) {
  const std::size_t i = w.index(id, "World.body_properties()");
  const RigidBody& body = w.world().bodies()[i];
  py::dict d;
  d["mass"] = body.mass();
  const Mat3& I = body.inertiaBody();
  d["inertia"] = py::make_tuple(py::make_tuple(I(0, 0), I(0, 1), I(0, 2)), py::make_tuple(I(1, 0), I(1, 1), I(1, 2)),
                                py::make_tuple(I(2, 0), I(2, 1), I(2, 2)));
  if (!body.isCompound()) {  // a compound's materials and filters are its shapes'
    const Material& m = rbsim::bodyMaterial(w.world(), id.id);
    d["restitution"] = m.restitution;
    d["friction_static"] = m.staticFriction;
    d["friction_kinetic"] = m.kineticFriction;
    py::dict filter;
    filter["category"] = body.filter().category;
    filter["mask"] = body.filter().mask;
    filter["group"] = body.filter().group;
    d["filter"] = filter;
  }
  return d;
}

void setJoint(PyWorld& w, const py::handle& jointIndex, const py::kwargs& keys) {
  const nlohmann::json change = toJson(givenKeywords(keys), kSetJointCall, "");
  const std::size_t j = jointArgument(w, jointIndex, kSetJointCall);  // waits for a step
  World& world = w.world();
  const JointChange c = parseJointChange(change, kSetJointCall, world.joints()[j]);
  const JointDef& d = c.def;
  try {
    const double max = d.type == JointDef::Type::Prismatic ? d.maxMotorForce : d.maxMotorTorque;
    const JointId id = jointIdAt(world, j);
    if (c.motor) rbsim::setJointMotor(world, id, d.motor, d.motorSpeed, max);
    if (c.limits) {
      const bool slider = d.type == JointDef::Type::Prismatic;
      rbsim::setJointLimits(world, id, d.limits, slider ? d.lowerTranslation : d.lowerAngle, slider ? d.upperTranslation : d.upperAngle);
    }
  } catch (const std::invalid_argument& e) {
    throw InputError(kSetJointCall, "", e.what());
  }
}

}  // namespace

void bindChanges(py::class_<PyWorld>& world) {
  world
      .def("set_body",
           [](PyWorld& w, const py::object& body, const py::kwargs& keys) { setBody(w, bodyArgument(body, kSetBodyCall), keys); },
           py::arg("body"),
           "set_body(self, /, body, *, mass=None, inertia=None, restitution=None, friction_static=None, "
           "friction_kinetic=None, filter=None)\n--\n\n"
           "-> None: changes a running body from the next step (PyBullet's changeDynamics), the keys of a scene's "
           "body with its checks: mass [kg] (alone it scales the inertia with it), inertia (3 x 3 [kg m^2] about the "
           "centre of mass, body frame, or its diagonal), restitution, friction_static, friction_kinetic, "
           "filter={\"category\", \"mask\", \"group\"} (keys left out keep theirs). The velocity stays (P = m v "
           "follows); the body wakes. None: unchanged")
      .def("body_properties", [](const PyWorld& w, const py::object& body) {
             return bodyProperties(w, bodyArgument(body, "World.body_properties()"));
           },
           py::arg("body"),
           "body_properties(self, /, body)\n--\n\n-> dict: mass, inertia, restitution, friction_static, "
           "friction_kinetic and filter as set_body takes them (a compound body: mass and inertia only)")
      .def("set_joint",
           [](PyWorld& w, const py::object& joint, const py::kwargs& keys) { setJoint(w, joint, keys); },
           py::arg("joint"),
           "set_joint(self, /, joint, *, motor=None, limits=None, twist=None)\n--\n\n"
           "-> None: changes a joint from the next step (PyBullet's setJointMotorControl2), the keys of a scene's "
           "joint with its checks: motor={\"speed\", \"max_torque\"} (a slider's \"max_force\"; keys left out keep "
           "the motor's) or False, limits=(lower, upper) (a ball's twist) or False. Its bodies wake. None: unchanged")
      .def("remove_joint",
           [](PyWorld& w, const py::object& joint) {
             const std::size_t j = jointArgument(w, joint, kRemoveJointCall);
             rbsim::removeJoint(w.world(), rbsim::jointIdAt(w.world(), j));
           },
           py::arg("joint"),
           "remove_joint(self, /, joint)\n--\n\n-> None: removes the joint (PyBullet's removeConstraint); later "
           "joints move down one index; its bodies wake and collide with each other again");
}

}  // namespace rbsim::python
