#include "rbsim/mass/mass_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "geometry/triangle_bvh.h"
#include "rbsim/io/input_error.h"

namespace rbsim {

namespace {

// A mesh whose volume is below this fraction of its bounding box's is treated as enclosing none.
constexpr double kMinVolumeFraction = 1e-12;
// Relative rounding allowed in I_max <= I_mid + I_min (exact for a flat plate).
constexpr double kTriangleInequalitySlack = 1e-9;
// Budget of the self-crossing check, in triangle pairs whose boxes overlap: a valid closed mesh
// needs ~50 per triangle (measured on spheres and tori), so this covers the largest mesh the loader
// accepts (kMaxMeshTriangles); only a mesh folded over itself many times needs more.
constexpr double kSelfCrossingPairTestsPerTriangle = 256.0;  // [pairs / triangle]

void requirePositiveFinite(double value, const char* field, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InputError("", field, std::string("expected a positive finite number [") + unit +
                                    "], got " + std::to_string(value));
  }
}

std::string describe(const Mesh& mesh) {
  double largest = 0.0;
  for (const Vec3& p : mesh.vertices) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  std::ostringstream where;
  where << "mesh '" << mesh.name << "' (largest |coordinate| " << largest << " m)";
  return where.str();
}

// Huge coordinates overflow the integrals (degree 5 in the coordinates for the inertia).
void requireFinite(const MassProperties& props, const Mesh& mesh) {
  if (!std::isfinite(props.volume) || !std::isfinite(props.mass) || !props.inertia.allFinite() ||
      !props.centerOfMass.allFinite()) {
    throw InputError("", "shape", describe(mesh) + ": its mass properties overflow double precision; "
                     "use smaller coordinates or a \"scale\"");
  }
}

// Rounding can still leave a tensor that is no body's (a sliver thinner than the precision of its
// coordinates, a tiny "scale" that underflows the moments). A solid's principal moments are
// positive and none exceeds the sum of the other two (the triangle inequality, with equality only
// for a flat plate); RigidBody would reject anything else as an internal error.
void requirePhysical(const MassProperties& props, const Mesh& mesh) {
  requireFinite(props, mesh);
  const Vec3 moments = Eigen::SelfAdjointEigenSolver<Mat3>(props.inertia, Eigen::EigenvaluesOnly).eigenvalues();
  const double slack = kTriangleInequalitySlack * moments.sum();
  if (!(moments.minCoeff() > 0.0) || moments.maxCoeff() > moments.sum() - moments.maxCoeff() + slack) {
    std::ostringstream problem;
    problem << describe(mesh) << ": its principal moments (" << moments.x() << ", " << moments.y() << ", "
            << moments.z() << ") kg m^2 are no solid's; the coordinates are too large or too far from "
            << "the origin for double precision: re-centre or scale the mesh";
    throw InputError("", "shape", problem.str());
  }
}

// Where a closed surface passes through itself the divergence theorem counts the overlap twice
// (or cancels it): the volume, the centre of mass and the inertia are then no solid's.
void requireNoSelfCrossing(const Mesh& mesh) {
  const double budget = kSelfCrossingPairTestsPerTriangle * double(mesh.triangles.size());
  const SelfCrossing crossing = TriangleBvh(mesh).selfCrossing(budget);
  std::ostringstream problem;
  if (crossing.found) {
    const Vec3& p = crossing.point;
    problem << "mesh '" << mesh.name << "': the surface crosses itself (triangles " << crossing.first << " and "
            << crossing.second << " meet near (" << p.x() << ", " << p.y() << ", " << p.z()
            << ") m): its volume is not defined";
  } else if (crossing.exhausted) {
    problem << "mesh '" << mesh.name << "': checking that the surface does not cross itself needs more than "
            << budget << " triangle pair tests (the boxes of its " << mesh.triangles.size()
            << " triangles overlap heavily); the limit is " << kSelfCrossingPairTestsPerTriangle << " per triangle";
  } else {
    return;
  }
  throw InputError("", "shape", problem.str());
}

// Exact integrals are only meaningful for a closed surface wound outward; say which test fails.
MassProperties exactProperties(const Mesh& mesh, double density) {
  const MeshCheck check = checkMesh(mesh);
  if (!check.closed || !check.consistentlyOriented || check.degenerateTriangles > 0) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' is not a closed, consistently wound "
                     "surface (" + check.problem + "); exact inertia needs one — use \"inertia\": "
                     "\"cube\" and a \"mass\" to approximate it");
  }
  requireNoSelfCrossing(mesh);
  const MassProperties props = polyhedralMassProperties(mesh, density);
  requireFinite(props, mesh);
  if (props.volume < 0.0) {
    throw InputError("", "shape", "mesh '" + mesh.name + "' encloses a negative volume (" +
                     std::to_string(props.volume) + " m^3): its triangles are wound inward; "
                     "reverse the winding");
  }
  // A closed surface folded flat (a triangle and its reverse) passes every topology test; what is
  // left of its volume after the signed sum cancels is rounding, not a solid.
  const Vec3 box = mesh.boundsMax() - mesh.boundsMin();
  if (props.volume <= kMinVolumeFraction * box.prod()) {
    std::ostringstream problem;
    problem << "mesh '" << mesh.name << "' encloses (almost) zero volume (" << props.volume << " m^3 in a "
            << box.x() << " x " << box.y() << " x " << box.z() << " m box): a solid needs volume";
    throw InputError("", "shape", problem.str());
  }
  return props;
}

}  // namespace

MassModel buildMassModel(Mesh mesh, std::optional<double> mass, std::optional<double> density,
                         InertiaMethod method, const Shape* shape) {
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
  const bool closedForm = shape != nullptr && (shape->isRound() || shape->type == ShapeType::Box);
  if (method == InertiaMethod::Exact && closedForm) {
    props.volume = roundOrBoxVolume(*shape);
    props.mass = mass ? *mass : *density * props.volume;
    props.inertia = roundOrBoxInertia(*shape, props.mass);
    requireFinite(props, mesh);
  } else if (method == InertiaMethod::Exact) {
    props = exactProperties(mesh, density.value_or(1.0));
    if (mass) {  // scale unit-density integrals to the requested mass
      props.inertia *= *mass / props.mass;
      props.mass = *mass;
    }
  } else {
    const double m = mass ? *mass : *density * exactProperties(mesh, 1.0).volume;
    props = cubeApproximation(mesh, m);
  }
  requirePhysical(props, mesh);

  MassModel model;
  model.fileMesh = std::make_shared<const Mesh>(mesh);
  translateMesh(mesh, props.centerOfMass);
  model.mass = props.mass;
  model.inertiaBody = props.inertia;
  model.centerOffset = props.centerOfMass;
  const Mat3 offDiagonal = props.inertia - Mat3(props.inertia.diagonal().asDiagonal());
  if (offDiagonal.cwiseAbs().maxCoeff() > kDiagonalInertiaTolerance * props.inertia.trace()) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(props.inertia);
    Mat3 axes = eig.eigenvectors();
    if (axes.determinant() < 0.0) axes.col(2) *= -1.0;  // a rotation, not a reflection
    for (Vec3& p : mesh.vertices) p = axes.transpose() * p;
    model.principalAxes = axes;
    model.inertiaBody = eig.eigenvalues().asDiagonal();
  }
  model.mesh = std::make_shared<const Mesh>(std::move(mesh));
  return model;
}

}  // namespace rbsim
