#pragma once
// Builders for the debug shapes the collision demos draw, so every demo outlines an AABB and draws
// a contact normal the same way. They only append to FrameData's lists; nothing here touches GL.
#include <vector>

#include <glm/glm.hpp>

#include "frame_data.h"

namespace rbsim::render {

// The 12 edges of the axis-aligned box [lo, hi].
void appendBoxLines(std::vector<DebugLine>& lines, const glm::vec3& lo, const glm::vec3& hi,
                    const glm::vec3& color, bool onTop = false);

// A segment from `from` to `to` with a small head at `to` made of four lines (a wire cone, so it
// reads as an arrow from any viewpoint). The head is 20% of the length, at most headLength [m].
void appendArrowLines(std::vector<DebugLine>& lines, const glm::vec3& from, const glm::vec3& to,
                      const glm::vec3& color, bool onTop = true, float headLength = 0.08f);

}  // namespace rbsim::render
