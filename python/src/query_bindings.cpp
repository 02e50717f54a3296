// World.ray_cast, ray_cast_batch, shape_cast, overlap, closest_point and query_aabb (issue 57):
// the scene queries of engine/include/rbsim/world/world_queries.h. A batch of rays goes in and
// comes out as NumPy arrays, one row per ray, cast with the GIL released (PyBullet's rayTestBatch,
// MuJoCo's mj_multiRay).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/io/input_error.h"
#include "rbsim/world/world_queries.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

Vec3 vec3Argument(const py::handle& value, const char* call, const char* field) {
  const Doubles a = doubleArrayArgument(value, call, field);
  if (a.ndim() != 1 || a.size() != 3) throw InputError(call, field, "expected 3 numbers");
  const Vec3 v(a.data()[0], a.data()[1], a.data()[2]);
  if (!v.allFinite()) throw InputError(call, field, "expected 3 finite numbers");
  return v;
}

// A distance >= 0 [m]; None: no limit.
double reachArgument(const py::handle& value, const char* call, const char* field) {
  if (value.is_none()) return std::numeric_limits<double>::infinity();
  const Doubles a = doubleArrayArgument(value, call, field);
  if (a.ndim() != 0 || !(a.data()[0] >= 0.0)) throw InputError(call, field, "expected a distance >= 0 [m] or None");
  return a.data()[0];
}

// A 64-bit set of categories as a Python int in [0, 2^64); None: `otherwise`.
std::uint64_t bitsArgument(const py::handle& value, const char* call, const char* field, std::uint64_t otherwise) {
  if (value.is_none()) return otherwise;
  if (!PyIndex_Check(value.ptr()) || PyBool_Check(value.ptr())) wrongType(call, field, "an int", value);
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) throw py::error_already_set();
  const unsigned long long bits = PyLong_AsUnsignedLongLong(index.ptr());
  if (PyErr_Occurred() != nullptr) {
    PyErr_Clear();
    throw InputError(call, field, "expected an int in [0, 2**64) whose bits are categories");
  }
  return bits;
}

QueryFilter filterArgument(const py::handle& category, const py::handle& mask, const py::handle& planes,
                           const char* call) {
  QueryFilter filter;
  filter.category = bitsArgument(category, call, "category", filter.category);
  filter.mask = bitsArgument(mask, call, "mask", filter.mask);
  if (!PyBool_Check(planes.ptr())) wrongType(call, "planes", "a bool", planes);
  filter.planes = planes.cast<bool>();
  return filter;
}

// A shape block as a scene's "shape" keys: {"type": "sphere", "radius": r}, {"type": "box",
// "extents": [x, y, z]} (full lengths) or {"type": "capsule", "radius": r, "length": l} (between
// the caps' centres, along the shape's y), at `position` turned by `orientation` (w, x, y, z).
QueryShape shapeArgument(const py::handle& shape, const py::handle& position, const py::handle& orientation,
                         const char* call) {
  if (!py::isinstance<py::dict>(shape)) wrongType(call, "shape", "a dict such as {\"type\": \"sphere\", \"radius\": 0.5}", shape);
  const py::dict keys = py::reinterpret_borrow<py::dict>(shape);
  const auto number = [&](const char* key) {
    if (!keys.contains(key)) throw InputError(call, std::string("shape.") + key, "missing");
    const Doubles a = doubleArrayArgument(keys[key], call, key);
    if (a.ndim() != 0 || !std::isfinite(a.data()[0])) throw InputError(call, std::string("shape.") + key, "expected a finite number");
    return a.data()[0];
  };
  const std::string type = keys.contains("type") ? stringArgument(keys["type"], call, "shape.type") : "";
  QueryShape q;
  q.position = vec3Argument(position, call, "position");
  if (!orientation.is_none()) {
    const Doubles a = doubleArrayArgument(orientation, call, "orientation");
    if (a.ndim() != 1 || a.size() != 4) throw InputError(call, "orientation", "expected (w, x, y, z)");
    q.orientation = Quat(a.data()[0], a.data()[1], a.data()[2], a.data()[3]);
  }
  if (type == "sphere") {
    q.kind = QueryShape::Kind::Sphere;
    q.radius = number("radius");
  } else if (type == "box") {
    q.kind = QueryShape::Kind::Box;
    q.halfExtents = 0.5 * vec3Argument(keys.contains("extents") ? py::handle(keys["extents"]) : py::handle(py::none()),
                                       call, "shape.extents");
  } else if (type == "capsule") {
    q.kind = QueryShape::Kind::Capsule;
    q.radius = number("radius");
    q.halfLength = 0.5 * number("length");
  } else {
    throw InputError(call, "shape.type", "expected \"sphere\", \"box\" or \"capsule\"");
  }
  return q;
}

py::tuple tupleOf(const Vec3& v) { return py::make_tuple(v.x(), v.y(), v.z()); }

py::dict hitDict(const PyWorld& w, const QueryHit& hit) {
  py::dict out;
  out["body"] = hit.isPlane ? py::object(py::none()) : py::cast(w.wrap(hit.body));
  out["plane"] = hit.isPlane ? py::object(py::int_(hit.plane)) : py::object(py::none());
  out["child"] = hit.child < 0 ? py::object(py::none()) : py::object(py::int_(hit.child));
  out["distance"] = hit.distance;
  out["point"] = tupleOf(hit.point);
  out["normal"] = tupleOf(hit.normal);
  return out;
}

py::object optionalHit(const PyWorld& w, const std::optional<QueryHit>& hit) {
  return hit ? py::object(hitDict(w, *hit)) : py::object(py::none());
}

// Runs a query on the World's engine call, InputError for what it refuses.
template <typename F>
auto engineCall(const char* call, F f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw InputError(call, "", e.what());
  }
}

std::vector<Vec3> rowsArgument(const py::handle& value, const char* call, const char* field) {
  const Doubles a = doubleArrayArgument(value, call, field);
  if (a.ndim() != 2 || a.shape(1) != 3) throw InputError(call, field, "expected an (N, 3) array");
  std::vector<Vec3> rows(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = Vec3(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
  return rows;
}

py::dict rayBatch(PyWorld& w, const py::handle& origins, const py::handle& directions, const py::handle& maxDistance,
                  const QueryFilter& filter) {
  constexpr const char* kCall = "World.ray_cast_batch()";
  const std::vector<Vec3> o = rowsArgument(origins, kCall, "origins"), d = rowsArgument(directions, kCall, "directions");
  if (o.size() != d.size()) {
    throw InputError(kCall, "directions", "expected as many rows as origins (" + std::to_string(o.size()) + "), got " +
                                              std::to_string(d.size()));
  }
  const double reach = reachArgument(maxDistance, kCall, "max_distance");
  std::vector<std::optional<QueryHit>> hits;
  const World& world = w.world();
  w.whileBusy([&] { hits = engineCall(kCall, [&] { return castRays(world, o, d, reach, filter); }); });
  const auto n = static_cast<py::ssize_t>(hits.size());
  py::array_t<bool> hit(n);
  py::array_t<std::int64_t> body(n), plane(n);
  py::array_t<std::int32_t> child(n);
  py::array_t<double> distance(n), point({n, py::ssize_t{3}}), normal({n, py::ssize_t{3}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (py::ssize_t i = 0; i < n; ++i) {
    const std::optional<QueryHit>& h = hits[static_cast<std::size_t>(i)];
    hit.mutable_data()[i] = h.has_value();
    body.mutable_data()[i] = h && !h->isPlane ? static_cast<std::int64_t>(world.indexOf(h->body)) : -1;
    plane.mutable_data()[i] = h && h->isPlane ? static_cast<std::int64_t>(h->plane) : -1;
    child.mutable_data()[i] = h ? h->child : -1;
    distance.mutable_data()[i] = h ? h->distance : std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      point.mutable_data()[3 * i + k] = h ? h->point[k] : nan;
      normal.mutable_data()[3 * i + k] = h ? h->normal[k] : nan;
    }
  }
  py::dict out;
  out["hit"] = hit;
  out["body"] = body;
  out["plane"] = plane;
  out["child"] = child;
  out["distance"] = distance;
  out["point"] = point;
  out["normal"] = normal;
  return out;
}

}  // namespace

void PyWorld::whileBusy(const std::function<void()>& work) {
  waitIdle();
  {
    const std::lock_guard<std::mutex> lock(busy_->mutex);
    busy_->stepping = true;
  }
  struct Idle {
    Busy& busy;
    ~Idle() {
      {
        const std::lock_guard<std::mutex> lock(busy.mutex);
        busy.stepping = false;
      }
      busy.idle.notify_all();
    }
  } idle{*busy_};
  py::gil_scoped_release release;
  work();
}

void bindQueries(py::class_<PyWorld>& world) {
  constexpr const char* kFilterDoc =
      "; category (int, default 1) and mask (int, default all bits) select shapes as Box2D's query filter "
      "does: a shape is seen when its category is in mask and its own mask holds category; planes=False leaves "
      "planes out";
  world.def(
      "ray_cast",
      [](const PyWorld& w, const py::object& origin, const py::object& direction, const py::object& maxDistance,
         const py::object& category, const py::object& mask, const py::object& planes) {
        constexpr const char* kCall = "World.ray_cast()";
        const Vec3 o = vec3Argument(origin, kCall, "origin"), d = vec3Argument(direction, kCall, "direction");
        if (!(d.stableNorm() > 0.0)) throw InputError(kCall, "direction", "expected a non-zero direction");
        const double reach = reachArgument(maxDistance, kCall, "max_distance");
        const QueryFilter filter = filterArgument(category, mask, planes, kCall);
        return optionalHit(w, engineCall(kCall, [&] { return castRay(w.world(), o, d, reach, filter); }));
      },
      py::arg("origin"), py::arg("direction"), py::arg("max_distance") = py::none(), py::kw_only(),
      py::arg("category") = py::none(), py::arg("mask") = py::none(), py::arg("planes") = true,
      (std::string("ray_cast(self, /, origin, direction, max_distance=None, *, category=None, mask=None, planes=True)\n--\n\n"
                   "-> dict | None: the first body or plane the ray meets (asleep and static ones too): "
                   "{\"body\": BodyId | None, \"plane\": int | None, \"child\": int | None (a compound's child), "
                   "\"distance\": m, \"point\": (x, y, z), \"normal\": (x, y, z)}; a start inside hits at distance 0; "
                   "max_distance None: no limit") + kFilterDoc).c_str());
  world.def(
      "ray_cast_batch",
      [](PyWorld& w, const py::object& origins, const py::object& directions, const py::object& maxDistance,
         const py::object& category, const py::object& mask, const py::object& planes) {
        return rayBatch(w, origins, directions, maxDistance,
                        filterArgument(category, mask, planes, "World.ray_cast_batch()"));
      },
      py::arg("origins"), py::arg("directions"), py::arg("max_distance") = py::none(), py::kw_only(),
      py::arg("category") = py::none(), py::arg("mask") = py::none(), py::arg("planes") = true,
      (std::string("ray_cast_batch(self, /, origins, directions, max_distance=None, *, category=None, mask=None, "
                   "planes=True)\n--\n\n-> dict of arrays, one row per ray: hit (N,) bool, body (N,) int64 (the "
                   "body's row in the state arrays, -1: none), plane (N,) int64 (-1: none), child (N,) int32 (-1: "
                   "none), distance (N,) (inf on a miss), point (N, 3) and normal (N, 3) (NaN on a miss); cast with "
                   "the GIL released") + kFilterDoc).c_str());
  world.def(
      "shape_cast",
      [](const PyWorld& w, const py::object& shape, const py::object& position, const py::object& direction,
         const py::object& maxDistance, const py::object& orientation, const py::object& category,
         const py::object& mask, const py::object& planes) {
        constexpr const char* kCall = "World.shape_cast()";
        const QueryShape q = shapeArgument(shape, position, orientation, kCall);
        const Vec3 d = vec3Argument(direction, kCall, "direction");
        const double reach = reachArgument(maxDistance, kCall, "max_distance");
        const QueryFilter filter = filterArgument(category, mask, planes, kCall);
        return optionalHit(w, engineCall(kCall, [&] { return castShape(w.world(), q, d, reach, filter); }));
      },
      py::arg("shape"), py::arg("position"), py::arg("direction"), py::arg("max_distance") = py::none(), py::kw_only(),
      py::arg("orientation") = py::none(), py::arg("category") = py::none(), py::arg("mask") = py::none(),
      py::arg("planes") = true,
      (std::string("shape_cast(self, /, shape, position, direction, max_distance=None, *, orientation=None, "
                   "category=None, mask=None, planes=True)\n--\n\n-> dict | None: the first body or plane a sphere, "
                   "box or capsule ({\"type\": \"sphere\", \"radius\": r}, {\"type\": \"box\", \"extents\": [x, y, z]}, "
                   "{\"type\": \"capsule\", \"radius\": r, \"length\": l}) meets when moved along direction, as "
                   "ray_cast's dict: distance moved, contact point, the hit surface's normal") + kFilterDoc).c_str());
  world.def(
      "overlap",
      [](const PyWorld& w, const py::object& shape, const py::object& position, const py::object& orientation,
         const py::object& category, const py::object& mask, const py::object& planes) {
        constexpr const char* kCall = "World.overlap()";
        const QueryShape q = shapeArgument(shape, position, orientation, kCall);
        const QueryFilter filter = filterArgument(category, mask, planes, kCall);
        py::list out;
        for (const QueryHit& hit : engineCall(kCall, [&] { return overlapShape(w.world(), q, filter); })) {
          py::dict d;
          d["body"] = hit.isPlane ? py::object(py::none()) : py::cast(w.wrap(hit.body));
          d["plane"] = hit.isPlane ? py::object(py::int_(hit.plane)) : py::object(py::none());
          d["child"] = hit.child < 0 ? py::object(py::none()) : py::object(py::int_(hit.child));
          out.append(d);
        }
        return out;
      },
      py::arg("shape"), py::arg("position"), py::kw_only(), py::arg("orientation") = py::none(),
      py::arg("category") = py::none(), py::arg("mask") = py::none(), py::arg("planes") = true,
      (std::string("overlap(self, /, shape, position, *, orientation=None, category=None, mask=None, planes=True)\n--\n\n"
                   "-> list[dict]: every body (by row) and then plane the shape (as shape_cast's) overlaps or "
                   "touches: {\"body\": BodyId | None, \"plane\": int | None, \"child\": int | None}") + kFilterDoc).c_str());
  world.def(
      "closest_point",
      [](const PyWorld& w, const py::object& point, const py::object& maxDistance, const py::object& category,
         const py::object& mask, const py::object& planes) {
        constexpr const char* kCall = "World.closest_point()";
        const Vec3 p = vec3Argument(point, kCall, "point");
        const double reach = reachArgument(maxDistance, kCall, "max_distance");
        const QueryFilter filter = filterArgument(category, mask, planes, kCall);
        return optionalHit(w, engineCall(kCall, [&] { return closestPoint(w.world(), p, reach, filter); }));
      },
      py::arg("point"), py::arg("max_distance") = py::none(), py::kw_only(), py::arg("category") = py::none(),
      py::arg("mask") = py::none(), py::arg("planes") = true,
      (std::string("closest_point(self, /, point, max_distance=None, *, category=None, mask=None, planes=True)\n--\n\n"
                   "-> dict | None: the surface point nearest point (as ray_cast's dict; distance < 0 inside a "
                   "solid, the deepest wins); None when nothing is within max_distance") + kFilterDoc).c_str());
  world.def(
      "query_aabb",
      [](const PyWorld& w, const py::object& lower, const py::object& upper, const py::object& category,
         const py::object& mask) {
        constexpr const char* kCall = "World.query_aabb()";
        const Aabb box{vec3Argument(lower, kCall, "lower"), vec3Argument(upper, kCall, "upper")};
        const QueryFilter filter = filterArgument(category, mask, py::bool_(true), kCall);
        py::list out;
        for (const BodyId id : engineCall(kCall, [&] { return queryAabb(w.world(), box, filter); })) out.append(w.wrap(id));
        return out;
      },
      py::arg("lower"), py::arg("upper"), py::kw_only(), py::arg("category") = py::none(), py::arg("mask") = py::none(),
      "query_aabb(self, /, lower, upper, *, category=None, mask=None)\n--\n\n-> list[BodyId]: the bodies, by row, "
      "whose bounding box (the broad phase's before its margin) overlaps the box from lower to upper; category "
      "and mask as ray_cast's");
}

}  // namespace rbsim::python
