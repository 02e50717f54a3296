// The overlay's time plots (OverlayData::plots, issue 24): stacked at the bottom right, each a
// frame with its title and unit, the value range on the left, the time window below, one line per
// series in its own colour and a legend. Drawn with ImGui's draw list: Debian's ImGui 1.86 has
// PlotLines, but one series, no axes and no units.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "overlay.h"
#include "pane_layout.h"

namespace rbsim::render {

namespace {

// Series colours, Tableau's first five (distinct for most colour vision).
constexpr ImU32 kSeriesColors[] = {IM_COL32(255, 158, 74, 255), IM_COL32(90, 170, 240, 255),
                                   IM_COL32(120, 200, 110, 255), IM_COL32(237, 102, 93, 255),
                                   IM_COL32(173, 139, 201, 255)};
constexpr float kPanelWidthFraction = 0.34f;   // of the image width [1]
constexpr float kPlotsHeightFraction = 0.62f;  // the stack, at most, of the image height [1]
constexpr float kMaxPlotHeightFraction = 0.22f;  // one plot, at most [1]
constexpr float kMinPlotLines = 5.0f;     // a plot's least height: title, two values, times [text lines]
constexpr float kMinPlotColumns = 14.0f;  // its least width beside the value labels [text line heights]
// The smallest range of a plot's value axis, relative to the values' size: the labels' 4
// significant digits tell its ends apart [1]. And absolute, for values at zero [the plot's unit].
constexpr float kMinRelativeSpan = 2e-3f;
constexpr float kMinSpan = 1e-6f;

// "1.23e+03" style for axis labels: 4 significant digits.
std::string axisNumber(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", static_cast<double>(value));
  return text;
}

}  // namespace

void Overlay::drawPlots(const OverlayData& data, float top) {
  if (data.plots.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushFont(bodyFont_);
  const float line = ImGui::GetTextLineHeight();
  const float margin = overlayMargin(static_cast<int>(io.DisplaySize.y));
  const float labelWidth = ImGui::CalcTextSize("-0.0000e+00").x;
  // In a small image the fractions leave no room for the text: a plot keeps kMinPlotLines of
  // height and kMinPlotColumns of width beside its labels, overlapping more of the picture.
  // Under the panel, the plots fill the info column of a comparison's panes (pane_layout.h),
  // where there is room for each to keep its least height; otherwise at the bottom right.
  const float count = static_cast<float>(data.plots.size());
  const float roomUnder = io.DisplaySize.y - data.plotsBottomInset - std::max(top, 0.0f) - 2.0f * margin - 2.0f * style.WindowPadding.y;
  const bool underPanel = data.plotsUnderPanel && roomUnder >= count * kMinPlotLines * line;
  const float columnWidth = static_cast<float>(infoColumnWidth(static_cast<int>(io.DisplaySize.x), static_cast<int>(io.DisplaySize.y))) - 2.0f * margin;
  const float preferredWidth = underPanel ? columnWidth : kPanelWidthFraction * io.DisplaySize.x;
  const float width = std::min(std::max(preferredWidth, labelWidth + kMinPlotColumns * line), io.DisplaySize.x - 2.0f * margin);
  const float room = underPanel ? roomUnder : kPlotsHeightFraction * io.DisplaySize.y - 2.0f * style.WindowPadding.y;
  const float plotHeight = std::max(kMinPlotLines * line, std::min(kMaxPlotHeightFraction * io.DisplaySize.y, room / count));
  const float height = plotHeight * count + 2.0f * style.WindowPadding.y;
  const float right = underPanel ? margin + width : data.plotsRight > 0.0f ? data.plotsRight : io.DisplaySize.x - margin;
  ImGui::SetNextWindowPos(ImVec2(right - width, io.DisplaySize.y - data.plotsBottomInset - height - margin));
  ImGui::SetNextWindowSize(ImVec2(width, height));  // fixed: see overlay.h
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoFocusOnAppearing;
  if (ImGui::Begin("##rbsim-plots", nullptr, flags)) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim = IM_COL32(175, 185, 200, 255);
    const ImU32 grid = IM_COL32(255, 255, 255, 40);
    ImVec2 origin = ImGui::GetCursorScreenPos();
    const float innerWidth = width - 2.0f * style.WindowPadding.x;
    for (const OverlayPlot& plot : data.plots) {
      // Title [unit], then the legend of a comparison, on one line.
      const std::string title = plot.unit.empty() ? plot.title : plot.title + " [" + plot.unit + "]";
      draw->AddText(origin, text, title.c_str());
      // The legend of a comparison follows the title, or takes a line of its own when too long.
      float legendWidth = 0.0f;
      for (const std::string& name : plot.legend) {
        if (!name.empty()) legendWidth += ImGui::CalcTextSize(name.c_str()).x + line;
      }
      const float titleWidth = ImGui::CalcTextSize(title.c_str()).x + line;
      const bool ownLine = legendWidth > 0.0f && titleWidth + legendWidth > innerWidth;
      ImVec2 at(ownLine ? origin.x : origin.x + titleWidth, ownLine ? origin.y + line : origin.y);
      for (std::size_t s = 0; s < plot.legend.size(); ++s) {
        if (plot.legend[s].empty()) continue;
        const ImU32 color = kSeriesColors[s % std::size(kSeriesColors)];
        draw->AddText(at, color, plot.legend[s].c_str());
        at.x += ImGui::CalcTextSize(plot.legend[s].c_str()).x + line;
      }
      // The frame: values left of it, time below it.
      const ImVec2 a(origin.x + labelWidth, origin.y + (ownLine ? 2.2f : 1.2f) * line);
      const ImVec2 b(origin.x + innerWidth, origin.y + plotHeight - 1.4f * line);
      float lo = INFINITY, hi = -INFINITY;
      for (std::size_t s = 0; s < plot.values.size(); ++s) {
        for (std::size_t i = 0; i < plot.values[s].size(); ++i) {
          const float v = plot.values[s][i];
          if (std::isfinite(v) && plot.times[s][i] >= plot.tMin) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
        }
      }
      if (!(lo <= hi)) lo = 0.0f, hi = 1.0f;  // nothing to show yet
      // The range spans at least kMinRelativeSpan of the values' size, so a conserved quantity
      // draws as the flat line it is instead of its rounding blown up to the plot's height.
      const float magnitude = std::max(std::abs(lo), std::abs(hi));
      const float span = std::max({hi - lo, kMinRelativeSpan * magnitude, kMinSpan});
      const float middle = 0.5f * (lo + hi);
      lo = middle - 0.54f * span;  // 8 % free above and below the lines
      hi = middle + 0.54f * span;
      draw->AddRect(a, b, grid);
      draw->AddLine(ImVec2(a.x, 0.5f * (a.y + b.y)), ImVec2(b.x, 0.5f * (a.y + b.y)), grid);
      // The middle value only where three labels fit without touching, the lowest where two do.
      const bool middleFits = b.y - a.y >= 3.0f * line, lowFits = b.y - a.y >= 2.0f * line;
      for (const auto& [value, y] : {std::pair{hi, a.y}, std::pair{0.5f * (lo + hi), 0.5f * (a.y + b.y) - 0.5f * line},
                                     std::pair{lo, b.y - line}}) {
        if ((!middleFits && value != hi && value != lo) || (!lowFits && value == lo)) continue;
        const std::string label = axisNumber(value);
        draw->AddText(ImVec2(a.x - ImGui::CalcTextSize(label.c_str()).x - 0.3f * line, y), dim, label.c_str());
      }
      const std::string from = axisNumber(plot.tMin) + " s", to = axisNumber(plot.tMax) + " s  t";
      draw->AddText(ImVec2(a.x, b.y + 0.1f * line), dim, from.c_str());
      draw->AddText(ImVec2(b.x - ImGui::CalcTextSize(to.c_str()).x, b.y + 0.1f * line), dim, to.c_str());
      const float tSpan = std::max(plot.tMax - plot.tMin, 1e-6f);
      draw->PushClipRect(a, b, true);
      for (std::size_t s = 0; s < plot.values.size(); ++s) {
        const ImU32 color = kSeriesColors[s % std::size(kSeriesColors)];
        std::vector<ImVec2> points;
        const auto flush = [&] {
          if (points.size() >= 2) draw->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, 2.0f);
          points.clear();
        };
        for (std::size_t i = 0; i < plot.values[s].size(); ++i) {
          const float v = plot.values[s][i];
          if (!std::isfinite(v)) {  // a gap
            flush();
            continue;
          }
          points.emplace_back(a.x + (plot.times[s][i] - plot.tMin) / tSpan * (b.x - a.x),
                              b.y - (v - lo) / (hi - lo) * (b.y - a.y));
        }
        flush();
      }
      draw->PopClipRect();
      origin.y += plotHeight;
    }
  }
  ImGui::End();
  ImGui::PopFont();
}

}  // namespace rbsim::render
