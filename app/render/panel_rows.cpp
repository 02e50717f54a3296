#include "panel_rows.h"

namespace rbsim::render {

std::vector<OverlayRow> panelRows(const std::vector<OverlayRow>& rows, PanelMode mode) {
  if (mode == PanelMode::Off) return {};
  if (mode == PanelMode::Full) return rows;
  std::vector<bool> chosen(rows.size(), false);
  for (std::size_t i = 0; i < rows.size(); ++i) chosen[i] = rows[i].level == RowLevel::Action;
  std::size_t count = 0;
  for (const RowLevel level : {RowLevel::Essential, RowLevel::Useful}) {
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].level != level) continue;
      // Essential rows are all kept, even past the budget; Useful ones fill what is left.
      if (level == RowLevel::Useful && count >= kCompactRows) break;
      chosen[i] = true;
      ++count;
    }
  }
  std::vector<OverlayRow> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (chosen[i]) out.push_back(rows[i]);
  }
  return out;
}

}  // namespace rbsim::render
