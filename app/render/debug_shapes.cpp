#include "debug_shapes.h"

#include <algorithm>
#include <cmath>

namespace rbsim::render {

void appendBoxLines(std::vector<DebugLine>& lines, const glm::vec3& lo, const glm::vec3& hi,
                    const glm::vec3& color, bool onTop) {
  // Corner k takes hi on axis i when bit i of k is set; an edge joins corners one bit apart.
  const auto corner = [&lo, &hi](int k) {
    return glm::vec3((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
  };
  for (int k = 0; k < 8; ++k) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if ((k & bit) == 0) lines.push_back({corner(k), corner(k | bit), color, onTop});
    }
  }
}

void appendArrowLines(std::vector<DebugLine>& lines, const glm::vec3& from, const glm::vec3& to,
                      const glm::vec3& color, bool onTop, float headLength) {
  lines.push_back({from, to, color, onTop});
  const glm::vec3 vector = to - from;
  const float length = glm::length(vector);
  if (!(length > 1e-6f)) return;  // also rejects NaN: no direction, no head
  const glm::vec3 dir = vector / length;
  const float head = std::min(0.2f * length, headLength);
  // Any vector not parallel to dir gives two directions across the arrow.
  const glm::vec3 helper = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(dir, helper));
  const glm::vec3 w = glm::cross(dir, u);
  const glm::vec3 base = to - head * dir;
  const float radius = 0.4f * head;
  for (const glm::vec3& across : {u, -u, w, -w}) {
    lines.push_back({to, base + radius * across, color, onTop});
  }
}

}  // namespace rbsim::render
