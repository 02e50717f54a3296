#include "window/picking.h"

#include <cmath>
#include <limits>

#include "render/projection.h"

namespace rbsim::app {

namespace {

// A ray this close to parallel with a plane (|cos| of the angle to the plane) meets it nowhere useful.
constexpr double kParallelCosine = 1e-9;  // [1]

// Moller and Trumbore, "Fast, minimum storage ray-triangle intersection" (1997): the distance
// along the ray, or a negative number when it misses or the triangle faces away.
double rayTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  if (det <= 0.0) return -1.0;  // back face or edge-on: the ray enters through front faces
  const Vec3 s = ray.origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Vec3 q = s.cross(e1);
  const double v = ray.direction.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return e2.dot(q) / det;
}

}  // namespace

Ray pixelRay(const render::Camera& camera, int width, int height, double x, double y) {
  const glm::mat4 inverse = glm::inverse(render::viewProjection(camera, width, height));
  const float ndcX = static_cast<float>(2.0 * (x + 0.5) / width - 1.0);
  const float ndcY = static_cast<float>(1.0 - 2.0 * (y + 0.5) / height);
  glm::vec4 nearPoint = inverse * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
  glm::vec4 farPoint = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
  nearPoint /= nearPoint.w;
  farPoint /= farPoint.w;
  Ray ray;
  ray.origin = Vec3(camera.eye.x, camera.eye.y, camera.eye.z);
  ray.direction = Vec3(farPoint.x - nearPoint.x, farPoint.y - nearPoint.y, farPoint.z - nearPoint.z).normalized();
  return ray;
}

std::optional<Pick> pickBody(const World& world, const Ray& ray) {
  std::optional<Pick> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& body = world.bodies()[i];
    const std::vector<Vec3>& vertices = body.worldVertices();
    for (const Triangle& t : body.mesh().triangles) {
      const double distance = rayTriangle(ray, vertices[t[0]], vertices[t[1]], vertices[t[2]]);
      if (distance > 0.0 && distance < nearest) {
        nearest = distance;
        best = Pick{i, ray.origin + distance * ray.direction, distance};
      }
    }
  }
  return best;
}

std::optional<Vec3> rayPlane(const Ray& ray, const Vec3& point, const Vec3& normal) {
  const double along = ray.direction.dot(normal);
  if (std::abs(along) < kParallelCosine) return std::nullopt;
  const double distance = (point - ray.origin).dot(normal) / along;
  return ray.origin + distance * ray.direction;
}

}  // namespace rbsim::app
