#pragma once
// From a shape and a mass or density to what a body needs: the mesh re-centred on its centre of
// mass, the mass and the body-space inertia tensor.
#include <memory>
#include <optional>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

struct MassModel {
  std::shared_ptr<const Mesh> mesh;  // re-centred: body origin = centre of mass
  double mass = 0.0;                 // [kg]
  Mat3 inertiaBody = Mat3::Zero();   // [kg m^2]
  Vec3 centerOffset = Vec3::Zero();  // centre of mass in the original mesh coordinates [m]
};

// Exactly one of mass [kg] or density [kg/m^3] is given. Exact inertia needs a closed,
// outward-wound, non-degenerate mesh; a density always needs one (for the volume), since the
// cube proxy's volume is not the body's. Throws InputError (field "mass", "density" or "shape")
// saying what is wrong; the scene loader adds the file and the JSON path.
// `shape`: when it is a sphere, capsule or box centred on the mesh's origin (the generators'),
// the exact method uses its closed form (shapes/shape.h) instead of the mesh's integrals, since
// the mesh only approximates a round shape (a 48 x 24 sphere holds 0.9 % less volume).
MassModel buildMassModel(Mesh mesh, std::optional<double> mass, std::optional<double> density,
                         InertiaMethod method, const Shape* shape = nullptr);

}  // namespace rbsim
