// World.particles(): every live particle of every particle system (seed 000's particle systems),
// one row each, systems in the order of the scene's "particles" block.
#include <cstdint>
#include <cstring>

#include <pybind11/numpy.h>

#include "py_world.h"
#include "rbsim/world/systems.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// One row of World.particles(); its field names are the array's.
struct ParticleRow {
  std::int64_t system;  // index in the scene's "particles" block
  double x[3];          // [m]
  double v[3];          // [m/s]
  double mass;          // [kg]; 0 for a pinned particle (infinite mass)
  double age;           // since birth [s]
  double lifetime;      // [s]; inf for one that never dies
};

}  // namespace

void bindParticles(py::class_<PyWorld>& c) {
  PYBIND11_NUMPY_DTYPE(ParticleRow, system, x, v, mass, age, lifetime);
  c.def(
      "particles",
      [](const PyWorld& w) {
        const std::vector<ParticleSystem>& systems = particleSystems(w.world());
        std::size_t total = 0;
        for (const ParticleSystem& s : systems) total += s.particles().count();
        py::array_t<ParticleRow> out(static_cast<py::ssize_t>(total));
        ParticleRow* row = out.mutable_data();
        if (total > 0) std::memset(static_cast<void*>(row), 0, total * sizeof(ParticleRow));
        for (std::size_t k = 0; k < systems.size(); ++k) {
          const ParticleStore& p = systems[k].particles();
          for (std::size_t i = 0; i < p.count(); ++i, ++row) {
            row->system = static_cast<std::int64_t>(k);
            for (int d = 0; d < 3; ++d) {
              row->x[d] = p.position[i][d];
              row->v[d] = p.velocity[i][d];
            }
            row->mass = p.mass(i);
            row->age = p.age[i];
            row->lifetime = p.lifetime[i];
          }
        }
        return out;
      },
      "particles(self, /)\n--\n\n-> structured array, one row per live particle: system (its index in the scene's \"particles\"), "
      "x (3) [m], v (3) [m/s], mass [kg] (0 when pinned), age [s], lifetime [s] (inf: never dies)");
}

}  // namespace rbsim::python
