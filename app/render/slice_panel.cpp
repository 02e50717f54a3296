// The overlay's maps (OverlayData::maps): images of coloured samples, each with its segments (a
// contour), a colour bar and a legend, side by side in a column at the image's right under a
// heading and notes. Drawn with ImGui's draw list, like the plots (plot_panel.cpp): the samples are
// filled rectangles, so the renderer needs no texture path of its own for them.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <imgui.h>

#include "overlay.h"
#include "overlay_style.h"
#include "pane_layout.h"
#include "text_wrap.h"

namespace rbsim::render {

namespace {

constexpr float kMapGapLines = 1.0f;        // between maps side by side [text line heights]
constexpr float kColorBarLines = 0.8f;      // the colour bar's height [text line heights]
constexpr float kSwatchLines = 0.8f;        // a legend swatch's side [text line heights]
constexpr float kReferenceRows = 720.0f;    // OverlayMap::lineWidthPixels is for this image height [px]

ImU32 color(const glm::vec3& c) {
  const auto byte = [](float x) { return static_cast<int>(std::lround(255.0f * std::clamp(x, 0.0f, 1.0f))); };
  return IM_COL32(byte(c.r), byte(c.g), byte(c.b), 255);
}

// The height a map's title, colour bar and legend take below and above its image [px].
float captionHeight(const OverlayMap& map, const ImFont* font, float width, float line) {
  float h = line;  // the title
  if (!map.colorBar.empty()) h += (kColorBarLines + 1.2f) * line;
  for (const OverlayLegendEntry& e : map.legend) {
    const float swatches = static_cast<float>(e.swatches.size()) * (kSwatchLines + 0.2f) * line + 0.3f * line;
    h += static_cast<float>(wrapLines(font, e.text, width - swatches).size()) * line;
  }
  return h + 0.5f * line;
}

}  // namespace

void Overlay::drawMaps(const OverlayData& data) {
  const OverlayMaps& maps = data.maps;
  if (maps.maps.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float margin = overlayMargin(static_cast<int>(io.DisplaySize.y));
  const float left = std::round(maps.leftFraction * io.DisplaySize.x);
  const ImVec2 pos(left, margin);
  const ImVec2 size(io.DisplaySize.x - margin - left, io.DisplaySize.y - 2.0f * margin);
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);  // fixed: see overlay.h
  const ImGuiWindowFlags flags = kFixedPanelFlags;
  if (ImGui::Begin("##rbsim-maps", nullptr, flags)) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim = IM_COL32(190, 198, 210, 255);
    const ImU32 title = ImGui::GetColorU32(kTitleColor);
    const float innerWidth = size.x - 2.0f * style.WindowPadding.x;
    const float x0 = pos.x + style.WindowPadding.x;
    float y = pos.y + style.WindowPadding.y;
    // Heading and notes, wrapped to the column.
    for (const std::string& l : wrapLines(titleFont_, maps.heading, innerWidth)) {
      draw->AddText(titleFont_, titleFont_->FontSize, ImVec2(x0, y), title, l.c_str());
      y += titleFont_->FontSize * 1.15f;
    }
    const float line = bodyFont_->FontSize * 1.15f;
    for (const std::string& note : maps.notes) {
      for (const std::string& l : wrapLines(bodyFont_, note, innerWidth)) {
        draw->AddText(bodyFont_, bodyFont_->FontSize, ImVec2(x0, y), text, l.c_str());
        y += line;
      }
    }
    y += 0.5f * line;
    // The maps: one sample size for all, the largest that leaves room for the tallest caption.
    const float count = static_cast<float>(maps.maps.size());
    const float mapWidth = (innerWidth - (count - 1.0f) * kMapGapLines * line) / count;
    float captions = 0.0f;
    for (const OverlayMap& m : maps.maps) captions = std::max(captions, captionHeight(m, bodyFont_, mapWidth, line));
    const float bottom = pos.y + size.y - style.WindowPadding.y;
    float sample = INFINITY;
    for (const OverlayMap& m : maps.maps) {
      if (m.columns <= 0 || m.rows <= 0) continue;
      sample = std::min({sample, mapWidth / static_cast<float>(m.columns), (bottom - y - captions) / static_cast<float>(m.rows)});
    }
    sample = std::isfinite(sample) ? std::max(1.0f, std::floor(sample)) : 1.0f;
    const float lineScale = io.DisplaySize.y / kReferenceRows;
    for (std::size_t k = 0; k < maps.maps.size(); ++k) {
      const OverlayMap& m = maps.maps[k];
      const float mx = x0 + static_cast<float>(k) * (mapWidth + kMapGapLines * line);
      float my = y;
      draw->AddText(bodyFont_, bodyFont_->FontSize, ImVec2(mx, my), title, m.title.c_str());
      my += line;
      const float w = sample * static_cast<float>(m.columns), h = sample * static_cast<float>(m.rows);
      // Row 0 at the bottom: v grows upwards, as the slice's second axis does.
      for (int v = 0; v < m.rows; ++v) {
        for (int u = 0; u < m.columns; ++u) {
          const ImVec2 a(mx + sample * static_cast<float>(u), my + sample * static_cast<float>(m.rows - 1 - v));
          draw->AddRectFilled(a, ImVec2(a.x + sample, a.y + sample), color(m.colors[static_cast<std::size_t>(v) * m.columns + u]));
        }
      }
      draw->PushClipRect(ImVec2(mx, my), ImVec2(mx + w, my + h), true);
      const auto at = [&](float u, float v) { return ImVec2(mx + (u + 0.5f) * sample, my + (static_cast<float>(m.rows) - 0.5f - v) * sample); };
      for (const glm::vec4& s : m.lines) {
        draw->AddLine(at(s.x, s.y), at(s.z, s.w), color(m.lineColor), m.lineWidthPixels * lineScale);
      }
      draw->PopClipRect();
      draw->AddRect(ImVec2(mx, my), ImVec2(mx + w, my + h), IM_COL32(255, 255, 255, 90));
      my += h + 0.4f * line;
      if (!m.colorBar.empty()) {
        const float step = w / static_cast<float>(m.colorBar.size());
        for (std::size_t i = 0; i < m.colorBar.size(); ++i) {
          const float a = mx + step * static_cast<float>(i);
          const ImU32 c0 = color(m.colorBar[i]), c1 = color(m.colorBar[std::min(i + 1, m.colorBar.size() - 1)]);
          draw->AddRectFilledMultiColor(ImVec2(a, my), ImVec2(a + step + 0.5f, my + kColorBarLines * line), c0, c1, c1, c0);
        }
        my += kColorBarLines * line;
        const std::size_t n = m.colorBarLabels.size();
        for (std::size_t i = 0; i < n; ++i) {
          const float tw = ImGui::CalcTextSize(m.colorBarLabels[i].c_str()).x;
          const float cx = mx + (n > 1 ? w * static_cast<float>(i) / static_cast<float>(n - 1) : 0.5f * w);
          draw->AddText(bodyFont_, bodyFont_->FontSize, ImVec2(std::clamp(cx - 0.5f * tw, mx, mx + w - tw), my), dim,
                        m.colorBarLabels[i].c_str());
        }
        my += 1.2f * line;
      }
      for (const OverlayLegendEntry& e : m.legend) {
        float sx = mx;
        for (const glm::vec3& c : e.swatches) {
          const ImVec2 a(sx, my + 0.5f * (line - kSwatchLines * line));
          draw->AddRectFilled(a, ImVec2(a.x + kSwatchLines * line, a.y + kSwatchLines * line), color(c));
          draw->AddRect(a, ImVec2(a.x + kSwatchLines * line, a.y + kSwatchLines * line), IM_COL32(255, 255, 255, 90));
          sx += (kSwatchLines + 0.2f) * line;
        }
        sx += 0.3f * line;
        for (const std::string& l : wrapLines(bodyFont_, e.text, mapWidth - (sx - mx))) {
          draw->AddText(bodyFont_, bodyFont_->FontSize, ImVec2(sx, my), text, l.c_str());
          my += line;
        }
      }
    }
  }
  ImGui::End();
}

}  // namespace rbsim::render
