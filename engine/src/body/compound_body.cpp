#include "rbsim/body/compound_body.h"

#include <cmath>
#include <stdexcept>

#include "rbsim/body/rigid_body.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/mass/mass_properties.h"

namespace rbsim {

namespace {

// A part's mass, centre of mass and inertia about it, in the part's frame.
MassProperties partMass(const CompoundPart& part, const std::string& where) {
  if (part.shape.type == ShapeType::ConvexHull) {
    if (!part.mesh) throw std::invalid_argument(where + "a convex hull needs its mesh");
    const MassProperties props = polyhedralMassProperties(*part.mesh, part.density);
    if (!(props.volume > 0.0)) throw std::invalid_argument(where + "its mesh encloses no volume (wound inward?)");
    return props;
  }
  MassProperties props;
  props.volume = roundOrBoxVolume(part.shape);
  props.mass = part.density * props.volume;
  props.inertia = roundOrBoxInertia(part.shape, props.mass);
  return props;
}

}  // namespace

BodyDef compoundBodyDef(const std::vector<CompoundPart>& parts, const std::string& name, std::optional<double> totalMass) {
  const std::string body = "body '" + name + "': ";
  if (parts.empty()) throw std::invalid_argument(body + "a compound body needs at least one shape");
  if (parts.size() > static_cast<std::size_t>(kMaxCompoundChildren)) {
    throw std::invalid_argument(body + std::to_string(parts.size()) + " shapes; expected at most " +
                                std::to_string(kMaxCompoundChildren));
  }
  if (totalMass && (!(*totalMass > 0.0) || !std::isfinite(*totalMass))) {
    throw std::invalid_argument(body + "mass must be a positive finite number [kg]");
  }
  std::vector<MassProperties> masses;
  double mass = 0.0;
  Vec3 moment = Vec3::Zero();  // sum of m_i c_i [kg m]
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const CompoundPart& part = parts[i];
    const std::string where = body + "shape " + std::to_string(i) + ": ";
    if (part.shape.type == ShapeType::Mesh) throw std::invalid_argument(where + "a non-convex mesh cannot be a compound's part");
    if (!(part.density > 0.0) || !std::isfinite(part.density)) {
      throw std::invalid_argument(where + "density must be a positive finite number [kg/m^3]");
    }
    if (!(std::abs(part.orientation.norm() - 1.0) <= kRotationTolerance) || !part.position.allFinite()) {
      throw std::invalid_argument(where + "expected a finite position and a unit orientation");
    }
    masses.push_back(partMass(part, where));
    const Vec3 centre = part.position + part.orientation * masses.back().centerOfMass;
    mass += masses.back().mass;
    moment += masses.back().mass * centre;
  }
  if (!(mass > 0.0) || !std::isfinite(mass)) throw std::invalid_argument(body + "its shapes' masses sum to no finite mass");
  const Vec3 centre = moment / mass;
  // Parallel axes: I = sum R_i I_i R_i^T + m_i (|d_i|^2 1 - d_i d_i^T), d_i from the common centre.
  Mat3 inertia = Mat3::Zero();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Mat3 R = parts[i].orientation.toRotationMatrix();
    const Vec3 d = parts[i].position + R * masses[i].centerOfMass - centre;
    inertia += R * masses[i].inertia * R.transpose() + masses[i].mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  const double scale = totalMass ? *totalMass / mass : 1.0;

  BodyDef def;
  def.name = name;
  def.mass = scale * mass;
  def.inertiaBody = scale * 0.5 * (inertia + inertia.transpose());
  def.fileFrame.centre = centre;
  auto merged = std::make_shared<Mesh>();
  merged->name = name;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const CompoundPart& part = parts[i];
    ChildShape child;
    child.shape = part.shape;
    child.position = part.position - centre;
    child.orientation = part.orientation.normalized();
    child.material = part.material;
    child.filter = part.filter;
    child.mesh = part.shape.type == ShapeType::ConvexHull ? part.mesh : std::make_shared<const Mesh>(displayMeshOf(part.shape));
    const auto first = static_cast<std::uint32_t>(merged->vertices.size());
    for (const Vec3& p : child.mesh->vertices) merged->vertices.push_back(child.orientation * p + child.position);
    for (const Triangle& t : child.mesh->triangles) merged->triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
    def.children.push_back(std::move(child));
  }
  // The merged vertices span the children's hull: what reads a body's one shape without knowing
  // its children sees that hull as a non-convex mesh.
  def.shape = Shape::mesh(*merged);
  def.mesh = std::move(merged);
  return def;
}

}  // namespace rbsim
