#pragma once
// The colours the variables panel (panel_draw.cpp) and the captions pinned to the image
// (overlay.cpp) share, so a title reads the same in both. ImGui's types: a private header.
#include <imgui.h>

namespace rbsim::render {

inline const ImVec4 kTitleColor(1.0f, 0.82f, 0.35f, 1.0f);  // amber: the panel's title and the captions

}  // namespace rbsim::render
