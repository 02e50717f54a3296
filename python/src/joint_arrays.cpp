// World.joints(): one row per joint, in the order add_joint numbered them, with what the joint
// does now (rbsim/world/joint_reading.h): PyBullet's getJointState, Box2D's joint getters.
#include <cstdint>
#include <cstring>

#include <pybind11/numpy.h>

#include "py_world.h"
#include "rbsim/dynamics/joint_ranges.h"  // jointTypeName
#include "rbsim/world/joint_reading.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// One row of World.joints(); its field names are the array's.
struct JointRow {
  std::int64_t body_a;  // row of body A in the state arrays
  std::int64_t body_b;  // row of body B, -1 for the world
  double angle;         // hinge: A relative to B about the axis, from where it was added [rad]; NaN otherwise
  double speed;         // hinge: A's turning relative to B about the axis [rad/s]; NaN otherwise
  double translation;   // prismatic: A's anchor from B's along the axis [m]; NaN otherwise
  double translation_speed;  // prismatic: its rate [m/s]; NaN otherwise
  double swing;         // ball: the angle between B's and A's copies of the axis [rad]; NaN otherwise
  double twist;         // ball: A's turning about the axis [rad]; NaN otherwise
  double axis[3];       // world frame, unit
  double anchor_a[3];   // A's copy of the pivot [m]
  double anchor_b[3];   // B's or the world's [m]
  double force[3];      // on A by the joint [N]
  double torque[3];     // on A by the joint, about its anchor [N m]
  char type[10];        // "ball", "hinge", "prismatic" or "weld"
  bool hinge;           // a hinge
};

void copy3(double (&out)[3], const Vec3& v) {
  for (int i = 0; i < 3; ++i) out[i] = v[i];
}

}  // namespace

void bindJoints(py::class_<PyWorld>& c) {
  PYBIND11_NUMPY_DTYPE(JointRow, body_a, body_b, angle, speed, translation, translation_speed, swing, twist, axis, anchor_a,
                       anchor_b, force, torque, type, hinge);
  c.def(
      "joints",
      [](const PyWorld& w) {
        const World& world = w.world();
        py::array_t<JointRow> out(static_cast<py::ssize_t>(world.joints().size()));
        JointRow* row = out.mutable_data();
        // The bytes after `hinge` are padding: zeroed, so equal readings are equal bytes.
        if (!world.joints().empty()) std::memset(static_cast<void*>(row), 0, world.joints().size() * sizeof(JointRow));
        for (std::size_t j = 0; j < world.joints().size(); ++j, ++row) {
          const Joint& joint = world.joints()[j];
          const JointReading r = readJoint(world, j);
          row->body_a = static_cast<std::int64_t>(world.indexOf(joint.def.bodyA));
          row->body_b = joint.def.bodyB == kWorldAnchor ? -1 : static_cast<std::int64_t>(world.indexOf(joint.def.bodyB));
          row->angle = r.angle;
          row->speed = r.speed;
          row->translation = r.translation;
          row->translation_speed = r.translationSpeed;
          row->swing = r.swing;
          row->twist = r.twist;
          std::strncpy(row->type, jointTypeName(joint.def.type), sizeof(row->type));
          copy3(row->axis, r.axis);
          copy3(row->anchor_a, r.anchorA);
          copy3(row->anchor_b, r.anchorB);
          copy3(row->force, r.force);
          copy3(row->torque, r.torque);
          row->hinge = joint.def.type == JointDef::Type::Hinge;
        }
        return out;
      },
      "joints(self, /)\n--\n\n-> structured array, one row per joint (the index add_joint returned): body_a, body_b (rows in the "
      "state arrays, -1 for the world), angle [rad] and speed [rad/s] of a hinge, translation [m] and "
      "translation_speed [m/s] of a prismatic joint, swing and twist [rad] of a ball joint (each NaN for the other types), "
      "axis (3), anchor_a (3), anchor_b (3) [m], force (3) [N] and torque (3) [N m] the joint puts on body A in the last "
      "substep, type (b\"ball\", b\"hinge\", b\"prismatic\", b\"weld\"), hinge");
}

}  // namespace rbsim::python
