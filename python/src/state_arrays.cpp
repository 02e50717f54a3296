// The state of every body as NumPy arrays (issue 23): one row per body, in World order (the
// index World.index_of gives). Each property fills a new array in one pass over the bodies: a
// view into the World's bodies would be cheaper still, but it would change under the caller at
// the next step (a history list of views holds one state many times) and dangle once add_body
// grows the body array, so every property is a snapshot the caller owns.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arguments.h"
#include "py_world.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// An (n, columns) array of doubles, row i filled by fill(body i, row pointer).
template <typename Fill>
py::array_t<double> rows(const World& world, py::ssize_t columns, Fill fill) {
  const std::vector<RigidBody>& bodies = world.bodies();
  py::array_t<double> out({static_cast<py::ssize_t>(bodies.size()), columns});
  double* data = out.mutable_data();
  for (const RigidBody& body : bodies) {
    fill(body, data);
    data += columns;
  }
  return out;
}

py::array_t<double> vectors(const World& world, const Vec3& (*get)(const RigidBody&)) {
  return rows(world, 3, [get](const RigidBody& b, double* row) {
    const Vec3& v = get(b);
    row[0] = v.x();
    row[1] = v.y();
    row[2] = v.z();
  });
}

py::array_t<double> scalars(const World& world, double (*get)(const World&, const RigidBody&)) {
  const std::vector<RigidBody>& bodies = world.bodies();
  py::array_t<double> out(static_cast<py::ssize_t>(bodies.size()));
  double* data = out.mutable_data();
  for (const RigidBody& body : bodies) *data++ = get(world, body);
  return out;
}

// Gravity's potential energy, -m g . x, zero at the origin [J].
double potentialEnergy(const World& world, const RigidBody& body) {
  return -body.mass() * world.settings().gravity.dot(body.position());
}

py::array_t<double> positions(const World& w) { return vectors(w, [](const RigidBody& b) -> const Vec3& { return b.position(); }); }
py::array_t<double> velocities(const World& w) { return vectors(w, [](const RigidBody& b) -> const Vec3& { return b.velocity(); }); }
py::array_t<double> angularVelocities(const World& w) {
  return vectors(w, [](const RigidBody& b) -> const Vec3& { return b.angularVelocity(); });
}
py::array_t<double> linearMomenta(const World& w) {
  return vectors(w, [](const RigidBody& b) -> const Vec3& { return b.state().linearMomentum; });
}
py::array_t<double> angularMomenta(const World& w) {
  return vectors(w, [](const RigidBody& b) -> const Vec3& { return b.state().angularMomentum; });
}
// (w, x, y, z), the order of the trace and of the scene format.
py::array_t<double> quaternions(const World& w) {
  return rows(w, 4, [](const RigidBody& b, double* row) {
    const Quat& q = b.orientation();
    row[0] = q.w();
    row[1] = q.x();
    row[2] = q.y();
    row[3] = q.z();
  });
}
// (n, 3, 3), R[i][r][c]: the columns are the body axes in world frame.
py::array_t<double> rotations(const World& world) {
  const std::vector<RigidBody>& bodies = world.bodies();
  py::array_t<double> out({static_cast<py::ssize_t>(bodies.size()), py::ssize_t{3}, py::ssize_t{3}});
  double* data = out.mutable_data();
  for (const RigidBody& body : bodies) {
    const Mat3& R = body.rotation();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) *data++ = R(r, c);
    }
  }
  return out;
}
py::array_t<double> kineticEnergies(const World& w) {
  return scalars(w, [](const World&, const RigidBody& b) { return b.kineticEnergy(); });
}
py::array_t<double> potentialEnergies(const World& w) { return scalars(w, potentialEnergy); }
py::array_t<double> masses(const World& w) { return scalars(w, [](const World&, const RigidBody& b) { return b.mass(); }); }

py::array_t<bool> awakeFlags(const World& world) {
  const std::vector<RigidBody>& bodies = world.bodies();
  py::array_t<bool> out(static_cast<py::ssize_t>(bodies.size()));
  bool* data = out.mutable_data();
  for (const RigidBody& body : bodies) *data++ = body.awake();
  return out;
}

py::array_t<double> pointArray(const std::vector<Vec3>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* data = out.mutable_data();
  for (const Vec3& p : points) {
    *data++ = p.x();
    *data++ = p.y();
    *data++ = p.z();
  }
  return out;
}

}  // namespace

void bindStateArrays(py::class_<PyWorld>& c) {
  const auto world = [](py::array_t<double> (*get)(const World&)) {
    return [get](const PyWorld& w) { return get(w.world()); };
  };
  c.def_property_readonly("x", world(positions), "(n, 3) centre-of-mass positions [m]")
      .def_property_readonly("q", world(quaternions), "(n, 4) orientations, unit quaternions (w, x, y, z)")
      .def_property_readonly("R", world(rotations), "(n, 3, 3) rotation matrices R(t), columns = body axes")
      .def_property_readonly("v", world(velocities), "(n, 3) velocities of the centres of mass [m/s]")
      .def_property_readonly("omega", world(angularVelocities), "(n, 3) angular velocities, world frame [rad/s]")
      .def_property_readonly("P", world(linearMomenta), "(n, 3) linear momenta P = m v [kg m/s]")
      .def_property_readonly("L", world(angularMomenta), "(n, 3) angular momenta L = I(t) omega [kg m^2/s]")
      .def_property_readonly("mass", world(masses), "(n,) masses [kg]")
      .def_property_readonly("ke", world(kineticEnergies), "(n,) kinetic energies (P.v + L.omega)/2 [J]")
      .def_property_readonly("pe", world(potentialEnergies), "(n,) gravity's potential energies -m g.x [J]")
      .def_property_readonly("awake", [](const PyWorld& w) { return awakeFlags(w.world()); }, "(n,) bool")
      .def(
          "state",
          [](const PyWorld& w) {
            const World& wd = w.world();
            py::dict d;
            d["t"] = wd.time();
            d["x"] = positions(wd);
            d["q"] = quaternions(wd);
            d["R"] = rotations(wd);
            d["v"] = velocities(wd);
            d["omega"] = angularVelocities(wd);
            d["P"] = linearMomenta(wd);
            d["L"] = angularMomenta(wd);
            d["ke"] = kineticEnergies(wd);
            d["pe"] = potentialEnergies(wd);
            return d;
          },
          "state(self, /)\n--\n\n-> dict: every state array at once, with the time t")
      .def(
          "vertices",
          [](const PyWorld& w, const py::object& body) {
            const PyBodyId& id = bodyArgument(body, "World.vertices()");
            return pointArray(w.world().bodies()[w.index(id, "World.vertices()")].worldVertices());
          },
          py::arg("body"), "vertices(self, /, body)\n--\n\n-> (k, 3) the body's vertices in world frame, p' = R p + x (seed 004) [m]")
      .def(
          "body_vertices",
          [](const PyWorld& w, const py::object& body) {
            const RigidBody& b = w.world().bodies()[w.index(bodyArgument(body, "World.body_vertices()"), "World.body_vertices()")];
            std::vector<Vec3> points(b.vertexCount());
            for (std::size_t i = 0; i < points.size(); ++i) points[i] = b.bodyVertex(i);
            return pointArray(points);
          },
          py::arg("body"), "body_vertices(self, /, body)\n--\n\n-> (k, 3) the body's vertices in body frame (origin at the centre of mass) [m]");
}

}  // namespace rbsim::python
