// World.contacts() (issue 39; PyBullet's getContactPoints, MuJoCo's data.contact): every contact
// point the World holds, sleeping pairs included, as one structured NumPy array. A sleeping pair
// keeps its manifold (its bodies have not moved since it was found) but is not solved: its
// impulses are NaN, and `awake` says so.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <pybind11/numpy.h>

#include "py_world.h"
#include "rbsim/collision/contact.h"
#include "rbsim/dynamics/solved_contact_point.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// One row of World.contacts(); its field names are the array's.
struct ContactRow {
  std::int64_t body_a;   // row of body A in the state arrays, -1 when A is a plane
  std::int64_t body_b;   // row of body B
  std::int64_t plane;    // index of the plane A, -1 for two bodies
  std::int64_t shape_a;  // which of a compound A's shapes touches (0 for a body of one shape, -1 for a plane)
  std::int64_t shape_b;  // which of a compound B's shapes touches (0 for a body of one shape)
  double point[3];       // world frame [m], midway between the surfaces
  double normal[3];      // unit, from A towards B
  double depth;          // [m], > 0 overlapping, <= 0 apart (speculative, within the margin)
  double normal_impulse;      // j_N of the last step [N s]; NaN asleep
  double friction_impulse[3]; // [N s]; NaN asleep
  bool awake;            // either body awake: the pair was solved in the last step
};

}  // namespace

void bindContacts(py::class_<PyWorld>& c) {
  PYBIND11_NUMPY_DTYPE(ContactRow, body_a, body_b, plane, shape_a, shape_b, point, normal, depth, normal_impulse, friction_impulse, awake);
  c.def(
      "contacts",
      [](const PyWorld& w) {
        const World& world = w.world();
        const std::vector<Contact>& contacts = world.contacts();
        const std::vector<SolvedContactPoint>& solved = world.contactPoints();
        // The solved points of contact k, in manifold order (the solver keeps it).
        std::vector<std::size_t> firstSolved(contacts.size(), solved.size()), solvedCount(contacts.size(), 0);
        for (std::size_t s = 0; s < solved.size(); ++s) {
          const std::size_t k = solved[s].contact;
          if (k >= contacts.size()) continue;
          if (solvedCount[k]++ == 0) firstSolved[k] = s;
        }
        std::size_t total = 0;
        for (const Contact& contact : contacts) total += static_cast<std::size_t>(contact.manifold.count);
        py::array_t<ContactRow> out(static_cast<py::ssize_t>(total));
        ContactRow* row = out.mutable_data();
        // The bytes after `awake` are padding: zeroed, so equal contacts are equal bytes (tobytes()).
        if (total > 0) std::memset(static_cast<void*>(row), 0, total * sizeof(ContactRow));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t k = 0; k < contacts.size(); ++k) {
          const Contact& contact = contacts[k];
          const bool plane = contact.kind == Contact::Kind::PlaneBody;
          const bool awake = world.bodies()[contact.b].awake() || (!plane && world.bodies()[contact.a].awake());
          const bool matched = solvedCount[k] == static_cast<std::size_t>(contact.manifold.count);
          for (int p = 0; p < contact.manifold.count; ++p, ++row) {
            const ContactPoint& point = contact.manifold.points[static_cast<std::size_t>(p)];
            row->body_a = plane ? -1 : static_cast<std::int64_t>(contact.a);
            row->body_b = static_cast<std::int64_t>(contact.b);
            row->plane = plane ? static_cast<std::int64_t>(contact.a) : -1;
            row->shape_a = plane ? -1 : static_cast<std::int64_t>(contact.childA);
            row->shape_b = static_cast<std::int64_t>(contact.childB);
            for (int i = 0; i < 3; ++i) {
              row->point[i] = point.position[i];
              row->normal[i] = contact.manifold.normal[i];
            }
            row->depth = point.depth;
            row->awake = awake;
            const SolvedContactPoint* s = awake && matched ? &solved[firstSolved[k] + static_cast<std::size_t>(p)] : nullptr;
            row->normal_impulse = s ? s->normalImpulse : nan;
            for (int i = 0; i < 3; ++i) row->friction_impulse[i] = s ? s->frictionImpulse[i] : nan;
          }
        }
        return out;
      },
      "contacts(self, /)\n--\n\n-> structured array, one row per contact point, sleeping pairs included: body_a (row in the "
      "state arrays, -1 for a plane), body_b, plane (-1 for two bodies), point (3), normal (3, from A towards B), "
      "shape_a, shape_b (which of a compound body's shapes: 0 for a body of one shape, -1 for a plane), depth [m], normal_impulse [N s], friction_impulse (3) [N s] (NaN for a sleeping pair, not solved), awake");
  c.def_property_readonly(
      "contact_count",
      [](const PyWorld& w) {
        std::size_t n = 0;
        for (const Contact& contact : w.world().contacts()) n += static_cast<std::size_t>(contact.manifold.count);
        return n;
      },
      "contact points now, sleeping pairs included (len(contacts()))");
}

}  // namespace rbsim::python
