#pragma once
// The colours and window flags the variables panel (panel_draw.cpp) and the captions pinned to the image
// (overlay.cpp) share, so a title reads the same in both. ImGui's types: a private header.
#include <imgui.h>

namespace rbsim::render {

// Every overlay window (panel, plots, slice maps) is fixed where the frame puts it: no title bar,
// no input, nothing saved between runs, never focused (overlay.h).
inline constexpr ImGuiWindowFlags kFixedPanelFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                                     ImGuiWindowFlags_NoFocusOnAppearing;
inline const ImVec4 kTitleColor(1.0f, 0.82f, 0.35f, 1.0f);  // amber: the panel's title and the captions

}  // namespace rbsim::render
