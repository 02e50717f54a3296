#include "rbsim/particles/emitter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/math/types.h"

namespace rbsim {

namespace {

// A helper axis is usable for n x helper while |n . helper| stays below this: far from parallel,
// so the cross product keeps its precision.
constexpr double kHelperCosine = 0.9;  // [1]

// Two unit vectors completing the unit n to a right-handed orthonormal basis.
void basisAround(const Vec3& n, Vec3& a, Vec3& b) {
  const Vec3 helper = std::abs(n.x()) < kHelperCosine ? Vec3::UnitX() : Vec3::UnitY();
  a = n.cross(helper).normalized();
  b = n.cross(a);
}

}  // namespace

Vec3 sampleCone(const Vec3& axis, double spread, UniformRandom& random) {
  const double cosTheta = 1.0 - random.next() * (1.0 - std::cos(spread));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = random.between(0.0, 2.0 * kPi);
  Vec3 a, b;
  basisAround(axis, a, b);
  return cosTheta * axis + sinTheta * (std::cos(phi) * a + std::sin(phi) * b);
}

Emitter::Emitter(const EmitterDef& def, const std::vector<RigidBody>& bodies) : def_(def) {
  if (def_.shape != EmitterShape::MeshSurface) return;
  mesh_ = bodies.at(def_.body).sharedMesh();
  cumulativeArea_ = cumulativeTriangleAreas(*mesh_);
  if (cumulativeArea_.empty() || !(cumulativeArea_.back() > 0.0) || !std::isfinite(cumulativeArea_.back())) {
    throw std::invalid_argument("mesh emitter: the surface of body '" + bodies[def_.body].name() +
                                "' has no finite, positive area to emit from");
  }
}

std::vector<double> cumulativeTriangleAreas(const Mesh& mesh) {
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    total += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
    cumulative.push_back(total);
  }
  return cumulative;
}

bool Emitter::bodyIntact(const std::vector<RigidBody>& bodies) const {
  return def_.shape != EmitterShape::MeshSurface || (def_.body < bodies.size() && bodies[def_.body].sharedMesh() == mesh_);
}

void Emitter::samplePlace(UniformRandom& random, const std::vector<RigidBody>& bodies, Vec3& position, Vec3& axis,
                          Vec3& surfaceVelocity) const {
  surfaceVelocity = Vec3::Zero();
  axis = def_.direction;
  switch (def_.shape) {
    case EmitterShape::Point:
      position = def_.position;
      return;
    case EmitterShape::Disc: {  // uniform over the area: r = R sqrt(u)
      Vec3 a, b;
      basisAround(def_.direction, a, b);
      const double r = def_.radius * std::sqrt(random.next()), phi = random.between(0.0, 2.0 * kPi);
      position = def_.position + r * (std::cos(phi) * a + std::sin(phi) * b);
      return;
    }
    case EmitterShape::Box: {
      const Vec3& h = def_.halfExtents;
      const double x = random.between(-h.x(), h.x()), y = random.between(-h.y(), h.y());
      position = def_.position + Vec3(x, y, random.between(-h.z(), h.z()));
      return;
    }
    case EmitterShape::MeshSurface: {
      // A triangle with probability proportional to its area, then a uniform point in it
      // (Osada et al., "Shape distributions", 2002: sqrt of the first variate).
      const RigidBody& body = bodies[def_.body];
      const double pick = random.next() * cumulativeArea_.back();
      const std::size_t k = static_cast<std::size_t>(
          std::upper_bound(cumulativeArea_.begin(), cumulativeArea_.end(), pick) - cumulativeArea_.begin());
      // The emitter's own mesh (emit() checked that the body still has it), never the body's
      // storage: a piece's mesh has other triangles.
      const Triangle& t = mesh_->triangles[std::min(k, cumulativeArea_.size() - 1)];
      const double s = std::sqrt(random.next()), w = random.next();
      const Vec3& a = mesh_->vertices[t[0]];
      const Vec3& b = mesh_->vertices[t[1]];
      const Vec3& c = mesh_->vertices[t[2]];
      const Vec3 local = (1.0 - s) * a + s * (1.0 - w) * b + s * w * c;
      position = body.bodyToWorld(local);
      axis = (body.rotation() * (b - a).cross(c - a)).normalized();  // outward (counter-clockwise)
      surfaceVelocity = body.velocity() + body.angularVelocity().cross(position - body.position());
      return;
    }
  }
}

void Emitter::spawn(std::size_t i, ParticleStore& store, UniformRandom& random,
                    const std::vector<RigidBody>& bodies) const {
  Vec3 position, axis, surfaceVelocity;
  samplePlace(random, bodies, position, axis, surfaceVelocity);
  const double spread = def_.spreadDegrees * kPi / 180.0;
  const Vec3 direction = sampleCone(axis, spread, random);
  store.position[i] = position;
  store.velocity[i] = surfaceVelocity + random.between(def_.speedMin, def_.speedMax) * direction;
  store.inverseMass[i] = 1.0 / random.between(def_.massMin, def_.massMax);
  store.age[i] = 0.0;
  store.lifetime[i] = std::isinf(def_.lifetimeMax) ? kImmortal : random.between(def_.lifetimeMin, def_.lifetimeMax);
  store.size[i] = static_cast<float>(random.between(def_.sizeMin, def_.sizeMax));
  Eigen::Vector3f color;
  for (int c = 0; c < 3; ++c) {
    const double scale = 1.0 + random.between(-def_.colorJitter, def_.colorJitter);
    color[c] = static_cast<float>(std::clamp(def_.color[c] * scale, 0.0, 1.0));
  }
  store.color[i] = color;
}

std::size_t Emitter::emit(double t, double dt, ParticleStore& store, UniformRandom& random,
                          const std::vector<RigidBody>& bodies) {
  if (t + dt <= def_.start || t >= def_.end || !bodyIntact(bodies)) return 0;
  std::size_t due = 0;
  if (!burstDone_) {
    due += def_.burst;
    burstDone_ = true;
  }
  // Only the part of the step inside [start, end) emits.
  const double active = std::min(t + dt, def_.end) - std::max(t, def_.start);
  pending_ += def_.rate * active;
  const double whole = std::floor(pending_);
  pending_ -= whole;
  due += static_cast<std::size_t>(whole);
  std::size_t lost = 0;
  for (std::size_t k = 0; k < due; ++k) {
    const std::size_t i = store.add();
    if (i == store.capacity()) {
      lost = due - k;
      break;
    }
    spawn(i, store, random, bodies);
  }
  return lost;
}

}  // namespace rbsim
