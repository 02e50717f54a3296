// Picking and the orbit camera of window mode: the ray through a pixel hits the body the camera
// projects there, at its surface; the orbit camera keeps its distance and target.
#include "window/picking.h"

#include <cmath>
#include <memory>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "render/projection.h"
#include "window/orbit_camera.h"

namespace rbsim::app {
namespace {

constexpr int kWidth = 640, kHeight = 360;

World twoBoxes() {
  Settings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  const Vec3 extents(1.0, 1.0, 1.0);
  auto mesh = std::make_shared<const Mesh>(makeBox(extents));
  for (int i = 0; i < 2; ++i) {
    BodyDef def;
    def.name = i == 0 ? "near" : "far";
    def.mesh = mesh;
    def.mass = 1.0;
    def.inertiaBody = cuboidInertia(1.0, extents);
    def.position = Vec3(i == 0 ? -1.0 : 2.0, 0.5, i == 0 ? 0.0 : -3.0);
    world.addBody(def);
  }
  return world;
}

render::Camera frontCamera() {
  render::Camera camera;
  camera.eye = glm::vec3(0.0f, 0.5f, 6.0f);
  camera.target = glm::vec3(0.0f, 0.5f, 0.0f);
  return camera;
}

// The pixel where the camera projects a world point.
std::pair<double, double> project(const render::Camera& camera, const Vec3& p) {
  const glm::vec4 clip = render::viewProjection(camera, kWidth, kHeight) *
                         glm::vec4(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), 1.0f);
  return {(clip.x / clip.w * 0.5 + 0.5) * kWidth - 0.5, (0.5 - clip.y / clip.w * 0.5) * kHeight - 0.5};
}

TEST(Picking, TheRayThroughABodysPixelHitsItsFrontFace) {
  const World world = twoBoxes();
  const render::Camera camera = frontCamera();
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec3 centre = world.bodies()[i].position();
    const auto [x, y] = project(camera, centre);
    const std::optional<Pick> pick = pickBody(world, pixelRay(camera, kWidth, kHeight, x, y));
    ASSERT_TRUE(pick.has_value()) << world.bodies()[i].name();
    EXPECT_EQ(pick->body, i);
    // The ray from the eye through the centre enters the front face, z = centre + 0.5.
    const Vec3 eye(camera.eye.x, camera.eye.y, camera.eye.z);
    const double along = (centre.z() + 0.5 - eye.z()) / (centre.z() - eye.z());
    EXPECT_TRUE((pick->point - (eye + along * (centre - eye))).norm() < 1e-4) << pick->point.transpose();
  }
}

TEST(Picking, EmptySkyAndTheNearerBodyWin) {
  World world = twoBoxes();
  const render::Camera camera = frontCamera();
  EXPECT_FALSE(pickBody(world, pixelRay(camera, kWidth, kHeight, 5.0, 5.0)).has_value());
  // Put the far box right behind the near one: the near one is picked.
  world.body(world.idAt(1)).setPosition(Vec3(-1.0, 0.5, -3.0));
  const auto [x, y] = project(camera, Vec3(-1.0, 0.5, 0.0));
  const std::optional<Pick> pick = pickBody(world, pixelRay(camera, kWidth, kHeight, x, y));
  ASSERT_TRUE(pick.has_value());
  EXPECT_EQ(pick->body, 0u);
}

TEST(Picking, RayPlaneMeetsThePlaneAndRejectsParallelRays) {
  const Ray ray{Vec3(0.0, 2.0, 0.0), Vec3(0.0, -1.0, 0.0)};
  const std::optional<Vec3> hit = rayPlane(ray, Vec3(5.0, 0.5, 5.0), Vec3::UnitY());
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR((*hit - Vec3(0.0, 0.5, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_FALSE(rayPlane(Ray{Vec3::Zero(), Vec3::UnitX()}, Vec3(0.0, 1.0, 0.0), Vec3::UnitY()).has_value());
}

TEST(OrbitCamera, StartsAsTheSceneCameraAndOrbitsAtItsDistance) {
  const render::Camera scene = frontCamera();
  OrbitCamera orbit(scene);
  EXPECT_EQ(orbit.camera().eye, scene.eye) << "until moved, exactly the scene's camera";
  const float distance = glm::length(scene.eye - scene.target);
  orbit.orbit(120.0f, -40.0f);
  EXPECT_NEAR(glm::length(orbit.camera().eye - orbit.camera().target), distance, 1e-4f);
  EXPECT_EQ(orbit.camera().target, scene.target);
  EXPECT_GT(glm::length(orbit.camera().eye - scene.eye), 0.5f);
  orbit.zoom(2.0f);
  EXPECT_NEAR(glm::length(orbit.camera().eye - orbit.camera().target), distance * kZoomPerNotch * kZoomPerNotch, 1e-4f);
  // Pitch stops short of the pole, so the view never flips.
  orbit.orbit(0.0f, 1e4f);
  EXPECT_LT(orbit.camera().eye.y - orbit.camera().target.y, glm::length(orbit.camera().eye - orbit.camera().target));
}

}  // namespace
}  // namespace rbsim::app
