#pragma once
// Which rows a panel shows (view.panel, issue 38): all of them in a full panel; in a compact one
// the Essential rows, then the Useful ones in order while fewer than kCompactRows are chosen, and
// the Action rows beside the budget, kept in the order the app gave them (a student reads the same rows in the same place).
#include <cstddef>
#include <vector>

#include "frame_data.h"

namespace rbsim::render {

// A compact panel's most rows: about what a 360-row video shows beside the scene [rows].
constexpr std::size_t kCompactRows = 8;

std::vector<OverlayRow> panelRows(const std::vector<OverlayRow>& rows, PanelMode mode);

}  // namespace rbsim::render
