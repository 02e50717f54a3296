// The overlay's time plots (OverlayData::plots, issues 24 and 38): stacked under the panel in the
// info column (or at the bottom right), each a frame with its title and unit, 1-2-5 ticks on the
// left (plot_ticks.h), the time axis below, one line per series in its own colour and a legend. Drawn with ImGui's draw list: Debian's ImGui 1.86 has
// PlotLines, but one series, no axes and no units.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "render/overlay_style.h"
#include "overlay.h"
#include "pane_layout.h"
#include "plot_ticks.h"
#include "text_wrap.h"

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
constexpr float kTickSpacingLines = 1.3f;  // value ticks at least this far apart [text lines]
constexpr float kTimeTickSpacingLabels = 1.6f;  // time ticks at least this far apart [label widths]

}  // namespace

float Overlay::leastPlotsHeight(const OverlayData& data) const {
  if (data.plots.empty()) return 0.0f;
  const float line = bodyFont_->FontSize;
  return static_cast<float>(data.plots.size()) * kMinPlotLines * line + 2.0f * ImGui::GetStyle().WindowPadding.y +
         overlayMargin(height_) + data.plotsBottomInset;
}

void Overlay::drawPlots(const OverlayData& data, float top) {
  if (data.plots.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushFont(bodyFont_);
  const float line = ImGui::GetTextLineHeight();
  const float margin = overlayMargin(static_cast<int>(io.DisplaySize.y));
  const float labelWidth = ImGui::CalcTextSize("-00.000").x;
  // In a small image the fractions leave no room for the text: a plot keeps kMinPlotLines of
  // height and kMinPlotColumns of width beside its labels, overlapping more of the picture.
  // Under the panel, the plots fill the info column of a comparison's panes (pane_layout.h),
  // where there is room for each to keep its least height; otherwise at the bottom right.
  const float count = static_cast<float>(data.plots.size());
  const float roomUnder = io.DisplaySize.y - data.plotsBottomInset - std::max(top, 0.0f) - 2.0f * margin - 2.0f * style.WindowPadding.y;
  const bool underPanel = data.plotsUnderPanel && roomUnder >= count * kMinPlotLines * line;
  const float columnWidth = static_cast<float>(infoColumnWidth(static_cast<int>(io.DisplaySize.x), static_cast<int>(io.DisplaySize.y), data.panel)) - 2.0f * margin;
  const float preferredWidth = underPanel ? columnWidth : kPanelWidthFraction * io.DisplaySize.x;
  const float width = std::min(std::max(preferredWidth, labelWidth + kMinPlotColumns * line), io.DisplaySize.x - 2.0f * margin);
  const float room = underPanel ? roomUnder : kPlotsHeightFraction * io.DisplaySize.y - 2.0f * style.WindowPadding.y;
  const float plotHeight = std::max(kMinPlotLines * line, std::min(kMaxPlotHeightFraction * io.DisplaySize.y, room / count));
  const float height = plotHeight * count + 2.0f * style.WindowPadding.y;
  const float right = underPanel ? margin + width : data.plotsRight > 0.0f ? data.plotsRight : io.DisplaySize.x - margin;
  ImGui::SetNextWindowPos(ImVec2(right - width, io.DisplaySize.y - data.plotsBottomInset - height - margin));
  ImGui::SetNextWindowSize(ImVec2(width, height));  // fixed: see overlay.h
  const ImGuiWindowFlags flags = kFixedPanelFlags;
  if (ImGui::Begin("##rbsim-plots", nullptr, flags)) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim = IM_COL32(175, 185, 200, 255);
    const ImU32 grid = IM_COL32(255, 255, 255, 40);
    ImVec2 origin = ImGui::GetCursorScreenPos();
    const float innerWidth = width - 2.0f * style.WindowPadding.x;
    for (const OverlayPlot& plot : data.plots) {
      // The value axis first: its shared power of ten goes into the title's unit.
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
      // Title [unit], then the legend of a comparison, on one line or on a line of its own.
      float legendWidth = 0.0f;
      for (const std::string& name : plot.legend) {
        if (!name.empty()) legendWidth += ImGui::CalcTextSize(name.c_str()).x + line;
      }
      // The title's line, and room for half of the top tick's label above the frame.
      const float frameTopLines = 1.7f;
      const float frameHeightGuess = plotHeight - (frameTopLines + 1.4f) * line;
      const int maxTicks = std::max(2, static_cast<int>(frameHeightGuess / (kTickSpacingLines * line)) + 1);
      const AxisTicks ticks = niceTicks(lo, hi, std::min(maxTicks, 5), plot.nonNegative);
      // A title wider than the plot wraps (no text is cut off); the frame moves down by the lines
      // it adds, which the plot's fixed height takes from the frame.
      const std::vector<std::string> titleLines =
          wrapLines(ImGui::GetFont(), plot.title + axisUnit(ticks, plot.unit), innerWidth);
      for (std::size_t k = 0; k < titleLines.size(); ++k) {
        draw->AddText(ImVec2(origin.x, origin.y + static_cast<float>(k) * line), text, titleLines[k].c_str());
      }
      const float extraLines = static_cast<float>(titleLines.size() - 1);
      const float lastTop = origin.y + extraLines * line;
      const float titleWidth = ImGui::CalcTextSize(titleLines.back().c_str()).x + line;
      const bool ownLine = legendWidth > 0.0f && titleWidth + legendWidth > innerWidth;
      ImVec2 at(ownLine ? origin.x : origin.x + titleWidth, ownLine ? lastTop + line : lastTop);
      for (std::size_t s = 0; s < plot.legend.size(); ++s) {
        if (plot.legend[s].empty()) continue;
        const ImU32 color = kSeriesColors[s % std::size(kSeriesColors)];
        draw->AddText(at, color, plot.legend[s].c_str());
        at.x += ImGui::CalcTextSize(plot.legend[s].c_str()).x + line;
      }
      // The frame: value ticks left of it, time ticks below it.
      float tickWidth = 0.0f;
      for (const std::string& label : ticks.labels) tickWidth = std::max(tickWidth, ImGui::CalcTextSize(label.c_str()).x);
      const float frameLeft = origin.x + std::max(labelWidth, tickWidth + 0.3f * line);
      const ImVec2 a(frameLeft, origin.y + (extraLines + (ownLine ? frameTopLines + 1.0f : frameTopLines)) * line);
      const ImVec2 b(origin.x + innerWidth, origin.y + plotHeight - 1.4f * line);
      lo = static_cast<float>(ticks.lo);
      hi = static_cast<float>(ticks.hi);
      draw->AddRect(a, b, grid);
      const float pixelsPerTick = (b.y - a.y) / std::max<float>(1.0f, static_cast<float>(ticks.values.size()) - 1.0f);
      const std::size_t every = pixelsPerTick >= line ? 1 : static_cast<std::size_t>(std::ceil(line / std::max(pixelsPerTick, 1.0f)));
      for (std::size_t k = 0; k < ticks.values.size(); ++k) {
        const float y = b.y - static_cast<float>((ticks.values[k] - ticks.lo) / (ticks.hi - ticks.lo)) * (b.y - a.y);
        if (k > 0 && k + 1 < ticks.values.size()) draw->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), grid);
        if (k % every != 0) continue;
        const std::string& label = ticks.labels[k];
        const float labelY = std::clamp(y - 0.5f * line, a.y - 0.5f * line, b.y - 0.5f * line);
        draw->AddText(ImVec2(a.x - ImGui::CalcTextSize(label.c_str()).x - 0.3f * line, labelY), dim, label.c_str());
      }
      // Time: ticks in whole seconds (or 1-2-5 parts of one) over the plot's window.
      const float timeLabelWidth = ImGui::CalcTextSize("000.0 s").x;
      const int maxTimeTicks = std::max(2, static_cast<int>((b.x - a.x) / (kTimeTickSpacingLabels * timeLabelWidth)) + 1);
      const AxisTicks time = niceTicks(plot.tMin, plot.tMax, maxTimeTicks, plot.tMin >= 0.0f);
      for (std::size_t k = 0; k < time.values.size(); ++k) {
        if (time.values[k] < plot.tMin - 1e-6 || time.values[k] > plot.tMax + 1e-6) continue;
        const float x = a.x + static_cast<float>((time.values[k] - plot.tMin) / std::max(plot.tMax - plot.tMin, 1e-6f)) * (b.x - a.x);
        const std::string label = time.labels[k] + (k + 1 == time.values.size() || time.values[k + 1] > plot.tMax + 1e-6 ? " s" : "");
        const float w = ImGui::CalcTextSize(label.c_str()).x;
        draw->AddLine(ImVec2(x, b.y), ImVec2(x, b.y + 0.2f * line), grid);
        draw->AddText(ImVec2(std::clamp(x - 0.5f * w, a.x - 0.5f * w, b.x - w), b.y + 0.1f * line), dim, label.c_str());
      }
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
