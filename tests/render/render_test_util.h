#pragma once
// Shared helpers for the renderer tests: a box body built the way the engine builds one
// (world vertices p' = R p + x), independent projection maths, pixel access and temp folders.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_data.h"

namespace rbsim::render::test {

// The shader folder of this checkout (never the environment, so a stale RBSIM_SHADER_DIR cannot
// make the tests pass or fail).
std::string shaderDir();

// 12 triangles over 8 shared corners, counter-clockwise seen from outside.
const std::vector<std::array<std::uint32_t, 3>>& boxTriangles();

// Corner k of a box with half extents `half`: signs from the bits of k.
glm::vec3 boxCorner(int k, const glm::vec3& half);

BodyView makeBox(const glm::vec3& centre, const glm::vec3& half, const glm::mat3& rotation,
                 const glm::vec3& color);

struct Rgb {
  int r, g, b;
};

// Pixel (x, y) of a top-down RGBA8 image, y = 0 being the top row.
Rgb pixelAt(const std::vector<std::uint8_t>& rgba, int width, int x, int y);

// Pixel coordinates (x right, y down, continuous: pixel i spans [i, i + 1)) of a world point,
// computed with glm::perspective and glm::lookAt directly rather than through the renderer.
glm::vec2 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& point);

// A fresh empty folder under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace rbsim::render::test
