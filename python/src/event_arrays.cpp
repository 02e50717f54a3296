// World.contact_events() (issue 57; Box3D's b3World_GetContactEvents, contactEvents(world)):
// the pairs of shapes that began and stopped touching, and the hits faster than hit_event_speed,
// over every step of the last step(n) call (a PyBullet user polls once per call), as a dict of
// NumPy arrays, one row per event. Bodies are named by their row in the state arrays now (-1 for
// a plane, or for a body no longer in the World) and by their BodyId (None for a plane), which
// stays the one name of a removed body.
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "py_world.h"

namespace py = pybind11;

namespace rbsim::python {

void gatherContactEvents(const World& world, StepEvents& out) {
  const ContactEvents& e = rbsim::contactEvents(world);
  if (e.begin.empty() && e.end.empty() && e.hit.empty()) return;
  const std::uint64_t step = world.stepCount() - 1;  // the step that made them
  out.events.begin.insert(out.events.begin.end(), e.begin.begin(), e.begin.end());
  out.events.end.insert(out.events.end.end(), e.end.begin(), e.end.end());
  out.events.hit.insert(out.events.hit.end(), e.hit.begin(), e.hit.end());
  out.beginStep.resize(out.events.begin.size(), step);
  out.endStep.resize(out.events.end.size(), step);
  out.hitStep.resize(out.events.hit.size(), step);
}

namespace {

py::array_t<std::int64_t> integers(std::size_t n) { return py::array_t<std::int64_t>(static_cast<py::ssize_t>(n)); }
py::array_t<double> vectors(std::size_t n) {
  return py::array_t<double>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(3)});
}

// The columns every kind of event has, under "<kind>_...": who touched whom, and at which step.
template <typename Event>
void pairColumns(const PyWorld& w, const std::string& kind, const std::vector<Event>& events,
                 const std::vector<std::uint64_t>& steps, py::dict& out) {
  const World& world = w.world();
  const std::size_t n = events.size();
  py::array_t<std::int64_t> a = integers(n), b = integers(n), plane = integers(n), childA = integers(n),
                             childB = integers(n), step = integers(n);
  // Object arrays (np.empty(n, dtype=object)): BodyIds are Python objects.
  const py::object empty = py::module_::import("numpy").attr("empty");
  py::object idA = empty(n, py::arg("dtype") = "O"), idB = empty(n, py::arg("dtype") = "O");
  const auto row = [&](BodyId id) { return world.isValid(id) ? static_cast<std::int64_t>(world.indexOf(id)) : -1; };
  for (std::size_t k = 0; k < n; ++k) {
    const ContactPair& p = events[k].pair;
    const bool isPlane = p.plane != kNoPlane;
    a.mutable_at(k) = isPlane ? -1 : row(p.bodyA);
    b.mutable_at(k) = row(p.bodyB);
    plane.mutable_at(k) = p.plane;
    childA.mutable_at(k) = p.childA;
    childB.mutable_at(k) = p.childB;
    step.mutable_at(k) = static_cast<std::int64_t>(steps[k]);
    idA.attr("__setitem__")(k, isPlane ? py::object(py::none()) : py::cast(w.wrap(p.bodyA)));
    idB.attr("__setitem__")(k, py::cast(w.wrap(p.bodyB)));
  }
  out[py::str(kind + "_a")] = a;
  out[py::str(kind + "_b")] = b;
  out[py::str(kind + "_plane")] = plane;
  out[py::str(kind + "_child_a")] = childA;
  out[py::str(kind + "_child_b")] = childB;
  out[py::str(kind + "_id_a")] = idA;
  out[py::str(kind + "_id_b")] = idB;
  out[py::str(kind + "_step")] = step;
}

template <typename Event, typename Get>
py::array_t<double> vectorColumn(const std::vector<Event>& events, Get get) {
  py::array_t<double> out = vectors(events.size());
  auto v = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < events.size(); ++k) {
    const Vec3& x = get(events[k]);
    for (int i = 0; i < 3; ++i) v(static_cast<py::ssize_t>(k), i) = x[i];
  }
  return out;
}

template <typename Event, typename Get>
py::array_t<double> scalarColumn(const std::vector<Event>& events, Get get) {
  py::array_t<double> out(static_cast<py::ssize_t>(events.size()));
  for (std::size_t k = 0; k < events.size(); ++k) out.mutable_at(k) = get(events[k]);
  return out;
}

}  // namespace

void bindContactEvents(py::class_<PyWorld>& c) {
  c.def(
      "contact_events",
      [](const PyWorld& w) {
        const StepEvents& s = w.stepEvents();
        const ContactEvents& e = s.events;
        py::dict out;
        pairColumns(w, "begin", e.begin, s.beginStep, out);
        out["begin_point"] = vectorColumn(e.begin, [](const ContactBeginEvent& x) -> const Vec3& { return x.point; });
        out["begin_normal"] = vectorColumn(e.begin, [](const ContactBeginEvent& x) -> const Vec3& { return x.normal; });
        out["begin_depth"] = scalarColumn(e.begin, [](const ContactBeginEvent& x) { return x.depth; });
        pairColumns(w, "end", e.end, s.endStep, out);
        pairColumns(w, "hit", e.hit, s.hitStep, out);
        out["hit_point"] = vectorColumn(e.hit, [](const ContactHitEvent& x) -> const Vec3& { return x.point; });
        out["hit_normal"] = vectorColumn(e.hit, [](const ContactHitEvent& x) -> const Vec3& { return x.normal; });
        out["hit_speed"] = scalarColumn(e.hit, [](const ContactHitEvent& x) { return x.approachSpeed; });
        return out;
      },
      "contact_events(self, /)\n--\n\n-> dict of NumPy arrays, one row per event, over every step of the last "
      "step(n) call: begin_*, end_*, hit_* each with _a, _b (row in the state arrays now; -1 for a plane or a "
      "removed body), _plane (-1 for two bodies), _child_a, _child_b (which shape of a compound; 0 for a body of "
      "one shape or a plane), _id_a, _id_b (BodyId, None for a plane), _step (the World's step count before the "
      "step); begin_point, begin_normal (N, 3) [m], begin_depth [m]; hit_point, hit_normal (N, 3), hit_speed [m/s]");
}

}  // namespace rbsim::python
