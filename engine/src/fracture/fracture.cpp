#include "rbsim/fracture/fracture.h"

#include <cmath>

#include "rbsim/mass/mass_properties.h"

namespace rbsim {

namespace {

double bodyDensity(const Mesh& mesh, double mass) { return mass / polyhedralMassProperties(mesh, 1.0).volume; }

}  // namespace

std::string checkFracturePattern(const FracturePattern& pattern, const BodyDef& body) {
  if (!(pattern.impulseThreshold > 0.0) || !std::isfinite(pattern.impulseThreshold)) {
    return "the breaking impulse must be a positive number of N s";
  }
  if (pattern.pieces.size() < 2) return "a body breaks into at least 2 pieces";
  const MassProperties whole = polyhedralMassProperties(*body.mesh, 1.0);
  const double size = (body.mesh->boundsMax() - body.mesh->boundsMin()).norm();
  // The comparisons below are written to fail on NaN: a volume that overflows must not pass them.
  if (!(whole.volume > 0.0) || !std::isfinite(whole.volume) || !std::isfinite(size)) {
    return "the body's volume (" + std::to_string(whole.volume) + " m^3) is not finite and positive";
  }
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  for (std::size_t k = 0; k < pattern.pieces.size(); ++k) {
    const Mesh& piece = *pattern.pieces[k];
    const MeshCheck check = checkMesh(piece);
    const MassProperties p = polyhedralMassProperties(piece, 1.0);
    if (!check.closed || !check.consistentlyOriented || !(p.volume > 0.0)) {
      return "piece " + std::to_string(k) + " is not a closed, outward-wound solid";
    }
    volume += p.volume;
    moment += p.volume * p.centerOfMass;
  }
  if (!(std::abs(volume - whole.volume) <= kFractureFitTolerance * whole.volume)) {
    return "the pieces' volumes sum to " + std::to_string(volume) + " m^3, the body's is " + std::to_string(whole.volume);
  }
  if (!((moment / volume - whole.centerOfMass).norm() <= kFractureFitTolerance * size)) {
    return "the pieces' centre of mass is not the body's";
  }
  const Mat3 exact = whole.inertia * (body.mass / whole.volume);
  if (!((exact - body.inertiaBody).norm() <= kFractureFitTolerance * exact.norm())) {
    return "the body's inertia is not the exact inertia of its mesh (use inertia \"exact\"), so the "
           "pieces could not keep its angular momentum";
  }
  return "";
}

std::vector<BodyDef> fracturePieces(const RigidBody& body, const FracturePattern& pattern, const Material& material) {
  const double density = bodyDensity(body.mesh(), body.mass());
  const Mat3& R = body.rotation();
  const Vec3 v = body.isStatic() ? Vec3::Zero() : body.velocity();
  const Vec3 omega = body.isStatic() ? Vec3::Zero() : body.angularVelocity();
  std::vector<BodyDef> defs;
  defs.reserve(pattern.pieces.size());
  for (std::size_t k = 0; k < pattern.pieces.size(); ++k) {
    const MassProperties p = polyhedralMassProperties(*pattern.pieces[k], density);
    auto mesh = std::make_shared<Mesh>(*pattern.pieces[k]);
    translateMesh(*mesh, p.centerOfMass);  // the piece's origin is its own centre of mass
    mesh->name = body.name() + "/" + std::to_string(k);
    const Vec3 r = R * p.centerOfMass;  // from the body's centre of mass to the piece's, world
    BodyDef def;
    def.name = mesh->name;
    def.mesh = std::move(mesh);
    def.mass = p.mass;
    def.inertiaBody = p.inertia;
    def.position = body.position() + r;
    def.orientation = body.orientation();
    def.velocity = v + omega.cross(r);  // seed 000 "Fracture": v_i = v + omega x r_i
    def.angularVelocity = omega;        // omega_i = omega
    def.material = material;
    defs.push_back(std::move(def));
  }
  return defs;
}

}  // namespace rbsim
