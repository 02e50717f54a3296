#pragma once
// From a shape and a mass or density to what a body needs: the mesh re-centred on its centre of
// mass, the mass and the body-space inertia tensor.
#include <memory>
#include <optional>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

// Seed 000 "Rigid Body Modeling": "rotating the object space rest state by U^-1 gives a diagonal
// inertia tensor". The body frame is the principal frame: its origin the centre of mass, its axes
// the principal axes, so I_body is diagonal. A mesh whose inertia is already diagonal in its own
// axes (a box, a sphere, anything symmetric about them) keeps them: the body frame is then the
// file's, moved to the centre of mass.
struct MassModel {
  std::shared_ptr<const Mesh> mesh;  // in the body (principal) frame
  double mass = 0.0;                 // [kg]
  Mat3 inertiaBody = Mat3::Zero();   // [kg m^2], diagonal
  Vec3 centerOffset = Vec3::Zero();  // centre of mass in the original mesh coordinates [m]
  // The principal axes in the original mesh's axes (a rotation): p_file = axes p_body + centerOffset.
  Mat3 principalAxes = Mat3::Identity();
  std::shared_ptr<const Mesh> fileMesh;  // the mesh as given, vertex for vertex
};

// Off-diagonal inertia below this fraction of the trace is rounding, and the axes are kept.
inline constexpr double kDiagonalInertiaTolerance = 1e-12;  // [1]

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
