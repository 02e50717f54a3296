#include "mass/mass_model.h"

#include <cmath>

#include "io/input_error.h"

namespace rbsim {

namespace {

void requirePositiveFinite(double value, const char* field, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InputError("", field, std::string("expected a positive finite number [") + unit +
                                    "], got " + std::to_string(value));
  }
}

// Exact integrals are only meaningful for a closed surface wound outward; say which test fails.
MassProperties exactProperties(const Mesh& mesh, double density) {
  const MeshCheck check = checkMesh(mesh);
  if (!check.closed || !check.consistentlyOriented || check.degenerateTriangles > 0) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' is not a closed, consistently wound "
                     "surface (" + check.problem + "); exact inertia needs one — use \"inertia\": "
                     "\"cube\" and a \"mass\" to approximate it");
  }
  const MassProperties props = polyhedralMassProperties(mesh, density);
  if (props.volume < 0.0) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' encloses a negative volume (" +
                     std::to_string(props.volume) + " m^3): its triangles are wound inward; "
                     "reverse the winding");
  }
  if (props.volume == 0.0) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' encloses zero volume");
  }
  return props;
}

}  // namespace

MassModel buildMassModel(Mesh mesh, std::optional<double> mass, std::optional<double> density,
                         InertiaMethod method) {
  if (mass.has_value() == density.has_value()) {
    throw InputError("", "mass", "give exactly one of \"mass\" [kg] or \"density\" [kg/m^3]");
  }
  if (mass) requirePositiveFinite(*mass, "mass", "kg");
  if (density) requirePositiveFinite(*density, "density", "kg/m^3");

  const Vec3 extents = mesh.boundsMax() - mesh.boundsMin();
  if (!(extents.minCoeff() > 0.0)) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' is flat (bounding box extents " +
                     std::to_string(extents.x()) + " x " + std::to_string(extents.y()) + " x " +
                     std::to_string(extents.z()) + " m): a solid needs volume");
  }

  MassProperties props;
  if (method == InertiaMethod::Exact) {
    props = exactProperties(mesh, density.value_or(1.0));
    if (mass) {  // scale unit-density integrals to the requested mass
      props.inertia *= *mass / props.mass;
      props.mass = *mass;
    }
  } else {
    const double m = mass ? *mass : *density * exactProperties(mesh, 1.0).volume;
    props = cubeApproximation(mesh, m);
  }

  translateMesh(mesh, props.centerOfMass);
  MassModel model;
  model.mesh = std::make_shared<const Mesh>(std::move(mesh));
  model.mass = props.mass;
  model.inertiaBody = props.inertia;
  model.centerOffset = props.centerOfMass;
  return model;
}

}  // namespace rbsim
