#include "rbsim/mass/mass_properties.h"

namespace rbsim {

const char* inertiaMethodName(InertiaMethod method) {
  return method == InertiaMethod::Cube ? "cube" : "exact";
}

bool parseInertiaMethod(const std::string& name, InertiaMethod& out) {
  if (name == "cube") { out = InertiaMethod::Cube; return true; }
  if (name == "exact") { out = InertiaMethod::Exact; return true; }
  return false;
}

Mat3 cuboidInertia(double mass, const Vec3& extents) {
  const Vec3 e2 = extents.cwiseProduct(extents);
  return (mass / 12.0) * Vec3(e2.y() + e2.z(), e2.x() + e2.z(), e2.x() + e2.y()).asDiagonal();
}

MassProperties cubeApproximation(const Mesh& mesh, double mass) {
  const Vec3 lo = mesh.boundsMin();
  const Vec3 hi = mesh.boundsMax();
  MassProperties props;
  props.mass = mass;
  props.volume = (hi - lo).prod();
  props.centerOfMass = 0.5 * (lo + hi);
  props.inertia = cuboidInertia(mass, hi - lo);
  return props;
}

namespace {

// Eberly 2002, "Subexpressions": per-coordinate polynomial terms of one triangle's integrals.
struct Subexpressions {
  double f1, f2, f3, g0, g1, g2;
};

Subexpressions subexpressions(double w0, double w1, double w2) {
  const double temp0 = w0 + w1;
  const double temp1 = w0 * w0;
  const double temp2 = temp1 + w1 * temp0;
  Subexpressions s;
  s.f1 = temp0 + w2;
  s.f2 = temp2 + w2 * s.f1;
  s.f3 = w0 * temp1 + w1 * temp2 + w2 * s.f2;
  s.g0 = s.f2 + w0 * (s.f1 + w0);
  s.g1 = s.f2 + w1 * (s.f1 + w1);
  s.g2 = s.f2 + w2 * (s.f1 + w2);
  return s;
}

}  // namespace

MassProperties polyhedralMassProperties(const Mesh& mesh, double density) {
  // Integrate about the bounding-box centre, not the file's origin: a mesh modelled far from
  // its origin would otherwise lose digits in the second moments (cancellation in I = J - m c^2).
  const Vec3 reference = 0.5 * (mesh.boundsMin() + mesh.boundsMax());

  // integral[0] = int 1, [1..3] = int x, y, z, [4..6] = int x^2, y^2, z^2, [7..9] = int xy, yz, zx
  double integral[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (const Triangle& tri : mesh.triangles) {
    const Vec3 p0 = mesh.vertices[tri[0]] - reference;
    const Vec3 p1 = mesh.vertices[tri[1]] - reference;
    const Vec3 p2 = mesh.vertices[tri[2]] - reference;
    const Vec3 d = (p1 - p0).cross(p2 - p0);  // twice the area times the outward normal
    const Subexpressions sx = subexpressions(p0.x(), p1.x(), p2.x());
    const Subexpressions sy = subexpressions(p0.y(), p1.y(), p2.y());
    const Subexpressions sz = subexpressions(p0.z(), p1.z(), p2.z());
    integral[0] += d.x() * sx.f1;
    integral[1] += d.x() * sx.f2;
    integral[2] += d.y() * sy.f2;
    integral[3] += d.z() * sz.f2;
    integral[4] += d.x() * sx.f3;
    integral[5] += d.y() * sy.f3;
    integral[6] += d.z() * sz.f3;
    integral[7] += d.x() * (p0.y() * sx.g0 + p1.y() * sx.g1 + p2.y() * sx.g2);
    integral[8] += d.y() * (p0.z() * sy.g0 + p1.z() * sy.g1 + p2.z() * sy.g2);
    integral[9] += d.z() * (p0.x() * sz.g0 + p1.x() * sz.g1 + p2.x() * sz.g2);
  }
  const double scale[10] = {1.0 / 6,  1.0 / 24, 1.0 / 24, 1.0 / 24,  1.0 / 60,
                            1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (int i = 0; i < 10; ++i) integral[i] *= scale[i];

  MassProperties props;
  props.volume = integral[0];
  props.mass = density * integral[0];
  if (integral[0] == 0.0) return props;  // degenerate: no centre of mass; callers reject it

  const Vec3 c = Vec3(integral[1], integral[2], integral[3]) / integral[0];  // about reference
  const double v = integral[0];
  // Second moments about the centre of mass by the parallel-axis theorem, per unit density.
  const double xx = integral[4] - v * c.x() * c.x();
  const double yy = integral[5] - v * c.y() * c.y();
  const double zz = integral[6] - v * c.z() * c.z();
  const double xy = integral[7] - v * c.x() * c.y();
  const double yz = integral[8] - v * c.y() * c.z();
  const double zx = integral[9] - v * c.z() * c.x();
  Mat3 inertia;
  inertia << yy + zz, -xy, -zx,
             -xy, xx + zz, -yz,
             -zx, -yz, xx + yy;
  props.inertia = density * inertia;
  props.centerOfMass = c + reference;
  return props;
}

}  // namespace rbsim
