#pragma once
// Picking a body under the pointer: the ray through a pixel, cast against every body's triangles
// (p' = R p + x, as the engine computed them), nearest hit first.
#include <cstddef>
#include <optional>

#include "rbsim/math/types.h"
#include "render/frame_data.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();  // unit
};

struct Pick {
  std::size_t body = 0;
  Vec3 point = Vec3::Zero();  // where the ray enters the body, world frame [m]
  double distance = 0.0;      // along the ray [m]
};

// The ray from the eye through the centre of pixel (x, y), y counted from the top.
Ray pixelRay(const render::Camera& camera, int width, int height, double x, double y);

// The nearest body the ray enters (triangles facing the ray; static bodies too), if any.
std::optional<Pick> pickBody(const World& world, const Ray& ray);

// Where the ray meets the plane through `point` with normal `normal`; nullopt when parallel.
std::optional<Vec3> rayPlane(const Ray& ray, const Vec3& point, const Vec3& normal);

}  // namespace rbsim::app
