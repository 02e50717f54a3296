#include "render_test_util.h"

#include <cstdlib>
#include <system_error>

#include <glm/gtc/matrix_transform.hpp>

namespace rbsim::render::test {

std::string shaderDir() { return RBSIM_TEST_SHADER_DIR; }

const std::vector<std::array<std::uint32_t, 3>>& boxTriangles() {
  // Corner index bits: 1 = +x, 2 = +y, 4 = +z.
  static const std::vector<std::array<std::uint32_t, 3>> triangles = {
      {0, 4, 6}, {0, 6, 2},  // -x
      {1, 3, 7}, {1, 7, 5},  // +x
      {0, 1, 5}, {0, 5, 4},  // -y
      {2, 6, 7}, {2, 7, 3},  // +y
      {0, 2, 3}, {0, 3, 1},  // -z
      {4, 5, 7}, {4, 7, 6},  // +z
  };
  return triangles;
}

glm::vec3 boxCorner(int k, const glm::vec3& half) {
  return {(k & 1) ? half.x : -half.x, (k & 2) ? half.y : -half.y, (k & 4) ? half.z : -half.z};
}

BodyView makeBox(const glm::vec3& centre, const glm::vec3& half, const glm::mat3& rotation,
                 const glm::vec3& color) {
  BodyView body;
  for (int k = 0; k < 8; ++k) body.worldVertices.push_back(rotation * boxCorner(k, half) + centre);
  body.triangles = &boxTriangles();
  body.position = centre;
  body.rotation = rotation;
  body.color = color;
  return body;
}

Rgb pixelAt(const std::vector<std::uint8_t>& rgba, int width, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

glm::vec2 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& point) {
  const glm::mat4 projection =
      glm::perspective(glm::radians(camera.fovYDegrees),
                       static_cast<float>(width) / static_cast<float>(height), camera.nearPlane,
                       camera.farPlane);
  const glm::mat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
  const glm::vec4 clip = projection * view * glm::vec4(point, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  // NDC y points up; image rows go down.
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width),
          (0.5f - ndc.y * 0.5f) * static_cast<float>(height)};
}

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "rbsim_render_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) std::abort();
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace rbsim::render::test
