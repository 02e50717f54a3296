// The overlay's panel (OverlayData's title, caption and rows), laid out line by line with the
// fonts it is drawn with so that no text leaves its box (panel_layout.h, issue 38), then drawn
// with ImGui's draw list in a fixed-size window (overlay.h says why fixed).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include "overlay.h"
#include "overlay_style.h"
#include "pane_layout.h"
#include "panel_rows.h"
#include "text_wrap.h"

namespace rbsim::render {

namespace {

const ImVec4 kCaptionColor(0.78f, 0.82f, 0.88f, 1.0f);
const ImVec4 kLabelColor(0.70f, 0.76f, 0.84f, 1.0f);
const ImVec4 kMoreColor(0.60f, 0.65f, 0.72f, 1.0f);

// A row measured: its label's lines, and its value's lines beside the label (one) or below it.
struct MeasuredRow {
  std::vector<std::string> label, value;
  bool valueBelow = false;
  RowLevel level = RowLevel::Useful;
  std::size_t lineCount() const { return label.size() + (valueBelow ? value.size() : 0); }
};

}  // namespace

PanelLayout Overlay::panelLayout(const OverlayData& data) const {
  PanelLayout out;
  const std::vector<OverlayRow> rows = panelRows(data.rows, data.panel);
  if (data.panel == PanelMode::Off || (data.title.empty() && data.caption.empty() && rows.empty())) return out;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float margin = overlayMargin(height_);
  const float gap = textWidth(bodyFont_, "  ");
  const float line = bodyFont_->FontSize, titleLine = titleFont_->FontSize;
  const float rowPad = style.CellPadding.y;

  // The panel has the info column's width (pane_layout.h) whether or not the frame keeps the
  // column: a width that followed the values would reflow the rows as the numbers change.
  float width = static_cast<float>(infoColumnWidth(width_, height_, data.panel)) - 2.0f * margin;
  width = std::min(width, static_cast<float>(width_) - 2.0f * margin);
  const float inner = width - 2.0f * style.WindowPadding.x;

  const std::vector<std::string> title = wrapLines(titleFont_, data.title, inner);
  std::vector<std::string> caption = data.caption.empty() ? std::vector<std::string>{} : wrapLines(bodyFont_, data.caption, inner);
  // Values are right-aligned, labels left-aligned: a value stays beside its own label when both fit
  // on the line, else it goes below, on lines of its own.
  std::vector<MeasuredRow> measured;
  for (const OverlayRow& row : rows) {
    MeasuredRow m;
    m.level = row.level;
    m.valueBelow = textWidth(bodyFont_, row.label) + gap + textWidth(bodyFont_, row.value) > inner;
    m.label = m.valueBelow ? wrapLines(bodyFont_, row.label, inner) : std::vector<std::string>{row.label};
    m.value = m.valueBelow ? wrapLines(bodyFont_, row.value, inner) : std::vector<std::string>{row.value};
    measured.push_back(std::move(m));
  }

  // Heights; past the room left above the plots, rows go (Detail first, then Useful, then
  // Essential; the last of each), then caption lines.
  const float room = static_cast<float>(height_) - 2.0f * margin - (data.plotsUnderPanel ? leastPlotsHeight(data) : 0.0f);
  const auto heightOf = [&](std::size_t captionLines, const std::vector<MeasuredRow>& shown, std::size_t hidden) {
    float h = 2.0f * style.WindowPadding.y + static_cast<float>(title.size()) * titleLine;
    if (captionLines > 0) h += style.ItemSpacing.y + static_cast<float>(captionLines) * line;
    if (!shown.empty() || hidden > 0) h += 2.0f * style.ItemSpacing.y;  // the separator
    for (const MeasuredRow& m : shown) h += static_cast<float>(m.lineCount()) * line + 2.0f * rowPad;
    if (hidden > 0) h += line + 2.0f * rowPad;
    return h;
  };
  std::size_t hidden = 0;
  while (!measured.empty() && heightOf(caption.size(), measured, hidden) > room) {
    std::size_t drop = measured.size() - 1;
    for (const RowLevel level : {RowLevel::Detail, RowLevel::Useful, RowLevel::Essential, RowLevel::Action}) {
      const auto it = std::find_if(measured.rbegin(), measured.rend(), [&](const MeasuredRow& m) { return m.level == level; });
      if (it != measured.rend()) {
        drop = static_cast<std::size_t>(measured.rend() - it) - 1;
        break;
      }
    }
    measured.erase(measured.begin() + static_cast<std::ptrdiff_t>(drop));
    ++hidden;
  }
  while (!caption.empty() && heightOf(caption.size(), measured, hidden) > room) {
    caption.pop_back();
    if (!caption.empty()) {
      std::string& last = caption.back();
      while (!last.empty() && textWidth(bodyFont_, last + " ...") > inner) last.pop_back();
      last += " ...";
    }
  }

  out.x = margin;
  out.y = margin;
  out.width = width;
  out.height = heightOf(caption.size(), measured, hidden);
  out.innerLeft = out.x + style.WindowPadding.x;
  out.innerRight = out.innerLeft + inner;
  float y = out.y + style.WindowPadding.y;
  const auto add = [&](const std::string& text, float x, PanelLine::Kind kind, ImFont* font) {
    out.lines.push_back({text, x, y, textWidth(font, text), font->FontSize, kind});
  };
  for (const std::string& t : title) {
    add(t, out.innerLeft, PanelLine::Kind::Title, titleFont_);
    y += titleLine;
  }
  if (!caption.empty()) y += style.ItemSpacing.y;
  for (const std::string& c : caption) {
    add(c, out.innerLeft, PanelLine::Kind::Caption, bodyFont_);
    y += line;
  }
  if (!measured.empty() || hidden > 0) y += 2.0f * style.ItemSpacing.y;
  for (const MeasuredRow& m : measured) {
    out.rowTops.push_back(y);
    y += rowPad;
    const float top = y;
    for (const std::string& l : m.label) {
      add(l, out.innerLeft, PanelLine::Kind::Label, bodyFont_);
      y += line;
    }
    // Right-aligned: with a monospace font, same-precision numbers line up on the point.
    if (!m.valueBelow) {
      const float w = textWidth(bodyFont_, m.value.front());
      out.lines.push_back({m.value.front(), out.innerRight - w, top, w, line, PanelLine::Kind::Value});
    } else {
      for (const std::string& v : m.value) {
        add(v, out.innerRight - textWidth(bodyFont_, v), PanelLine::Kind::Value, bodyFont_);
        y += line;
      }
    }
    y += rowPad;
    out.rowBottoms.push_back(y);
  }
  if (hidden > 0) {
    y += rowPad;
    add("... " + std::to_string(hidden) + (hidden == 1 ? " more row" : " more rows") +
            (data.panel == PanelMode::Full ? "" : " (view.panel full)"),
        out.innerLeft, PanelLine::Kind::More, bodyFont_);
  }
  out.shownRows = measured.size();
  out.hiddenRows = hidden;
  return out;
}

float Overlay::drawPanel(const OverlayData& data) {
  const PanelLayout layout = panelLayout(data);
  if (layout.width <= 0.0f) return 0.0f;
  ImGui::SetNextWindowPos(ImVec2(layout.x, layout.y));
  ImGui::SetNextWindowSize(ImVec2(layout.width, layout.height));
  const ImGuiWindowFlags flags = kFixedPanelFlags;
  if (ImGui::Begin("##rbsim-overlay", nullptr, flags)) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float left = layout.x + 0.5f * ImGui::GetStyle().WindowPadding.x;
    const float right = layout.x + layout.width - 0.5f * ImGui::GetStyle().WindowPadding.x;
    if (!layout.rowTops.empty()) {
      const float separator = layout.rowTops.front() - ImGui::GetStyle().ItemSpacing.y;
      draw->AddLine(ImVec2(left, separator), ImVec2(right, separator), ImGui::GetColorU32(ImGuiCol_Separator));
    }
    for (std::size_t r = 1; r < layout.rowTops.size(); r += 2) {
      draw->AddRectFilled(ImVec2(left, layout.rowTops[r]), ImVec2(right, layout.rowBottoms[r]),
                          ImGui::GetColorU32(ImGuiCol_TableRowBgAlt));
    }
    for (const PanelLine& l : layout.lines) {
      ImFont* font = l.kind == PanelLine::Kind::Title ? titleFont_ : bodyFont_;
      const ImVec4 color = l.kind == PanelLine::Kind::Title     ? kTitleColor
                           : l.kind == PanelLine::Kind::Caption ? kCaptionColor
                           : l.kind == PanelLine::Kind::Label   ? kLabelColor
                           : l.kind == PanelLine::Kind::More    ? kMoreColor
                                                                : ImGui::GetStyle().Colors[ImGuiCol_Text];
      draw->AddText(font, font->FontSize, ImVec2(l.x, l.y), ImGui::GetColorU32(color), l.text.c_str());
    }
  }
  ImGui::End();
  return layout.y + layout.height;
}

PanelLayout Overlay::layoutPanel(const OverlayData& data) {
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
  ImGui_ImplOpenGL2_NewFrame();  // builds the font atlas on first use
  ImGui::NewFrame();
  PanelLayout layout = panelLayout(data);
  ImGui::EndFrame();
  return layout;
}

}  // namespace rbsim::render
