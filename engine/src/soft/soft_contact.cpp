#include "soft/soft_contact.h"

#include <cmath>

#include "rbsim/dynamics/impulse.h"

namespace rbsim {

int collideSoftWithRigid(SoftBody& soft, std::vector<RigidBody>& bodies, const std::vector<BodySolid>& shapes,
                         const std::vector<Material>& materials, const Material& softMaterial) {
  int touching = 0;
  std::vector<Vec3>& x = soft.positions();
  std::vector<Vec3>& v = soft.velocities();
  const std::vector<double>& m = soft.nodeMasses();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    RigidBody& body = bodies[b];
    const BodySolid& shape = shapes[b];
    const Material material = combine(softMaterial, materials[b]);
    const Mat3& R = body.rotation();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3 arm = x[i] - body.position();
      if (arm.squaredNorm() > shape.convex.boundingRadius * shape.convex.boundingRadius) continue;
      const SurfaceQuery surface = querySurface(shape, R.transpose() * arm);
      const double largest = surface.distance;
      if (!(largest < 0.0)) continue;
      ++touching;
      const Vec3 n = R * surface.normal;  // out of the body, towards the node
      x[i] -= largest * n;
      const Vec3 r = x[i] - body.position();
      const Vec3 u = v[i] - (body.velocity() + body.angularVelocity().cross(r));
      const double un = u.dot(n);
      if (un >= 0.0) continue;
      const double inverseMassBody = !body.isDynamic() ? 0.0 : 1.0 / body.mass();
      const Mat3 inverseInertia = !body.isDynamic() ? Mat3::Zero() : Mat3(body.inverseInertiaWorld());
      const Mat3 k = (1.0 / m[i]) * Mat3::Identity() + impulseFactor(inverseMassBody, inverseInertia, r);
      const double jn = -(1.0 + material.restitution) * un / n.dot(k * n);
      Vec3 j = jn * n;
      const Vec3 ut = u - un * n;
      if (ut.norm() > 0.0) {
        const Vec3 t = ut.normalized();
        const double stop = ut.norm() / t.dot(k * t);  // the impulse that stops the slip
        j -= std::min(stop, (stop <= material.staticFriction * jn ? material.staticFriction : material.kineticFriction) * jn) * t;
      }
      v[i] += j / m[i];
      if (body.isDynamic()) {  // a kinematic body keeps its prescribed motion
        BodyState state = body.state();
        state.linearMomentum -= j;
        state.angularMomentum -= r.cross(j);
        body.setState(state);
        body.wake();
      }
    }
  }
  return touching;
}

}  // namespace rbsim
