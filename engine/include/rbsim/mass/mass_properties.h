#pragma once
// Mass, centre of mass and inertia tensor about the centre of mass, in body axes.
#include <string>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct MassProperties {
  double mass = 0.0;                 // [kg]
  double volume = 0.0;               // [m^3], signed for the polyhedral method (< 0: inverted winding)
  Vec3 centerOfMass = Vec3::Zero();  // [m], in the mesh's own coordinates
  Mat3 inertia = Mat3::Zero();       // [kg m^2], about the centre of mass, mesh axes
};

enum class InertiaMethod {
  Cube,   // seed 004 "Inertial tensor: cube approximation": the bounding box as a solid cuboid
  Exact,  // exact polyhedral integrals of a closed triangle mesh (Mirtich 1996, Eberly 2002)
};

const char* inertiaMethodName(InertiaMethod method);
bool parseInertiaMethod(const std::string& name, InertiaMethod& out);

// Solid cuboid of full extents e and mass m: I = m/12 diag(ey^2 + ez^2, ex^2 + ez^2, ex^2 + ey^2).
Mat3 cuboidInertia(double mass, const Vec3& extents);

// Seed 004's cube approximation: the mesh's axis-aligned bounding box stands in for the body,
// so the centre of mass is the box centre and the inertia is cuboidInertia(mass, box extents).
MassProperties cubeApproximation(const Mesh& mesh, double mass);

// Exact mass properties of the solid bounded by a closed, outward-wound triangle mesh of uniform
// density [kg/m^3]: the divergence-theorem integrals of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx
// over the polyhedron (Mirtich 1996, "Fast and Accurate Computation of Polyhedral Mass
// Properties"; Eberly 2002, "Polyhedral Mass Properties (Revisited)"). The volume is signed:
// a mesh wound inward gives a negative volume and mass, which callers must reject.
MassProperties polyhedralMassProperties(const Mesh& mesh, double density);

}  // namespace rbsim
