#include "overlay.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include "gl_api.h"
#include "overlay_style.h"
#include "pane_layout.h"
#include "render_error.h"

namespace rbsim::render {

namespace {

// Captions pinned to the image (OverlayLabel) are this many times the panel's text size: they
// name what a whole region of the image shows and are read from across the frame [1].
constexpr float kLabelFontScale = 1.6f;

constexpr const char* kMonoFontPaths[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
    "/usr/share/fonts/TTF/DejaVuSansMono.ttf",
};

ImFont* loadFont(ImGuiIO& io, float sizePx) {
  for (const char* path : kMonoFontPaths) {
    if (std::filesystem::exists(path)) {
      ImFontConfig config;
      config.OversampleH = 2;  // sharper glyph edges at fractional positions
      if (ImFont* font = io.Fonts->AddFontFromFileTTF(path, sizePx, &config)) return font;
    }
  }
  // ProggyClean is a 13 px bitmap-style monospace font: scale it in whole steps to keep it crisp.
  ImFontConfig config;
  config.SizePixels = 13.0f * std::max(1.0f, std::round(sizePx / 13.0f));
  return io.Fonts->AddFontDefault(&config);
}

void applyStyle() {
  ImGuiStyle& style = ImGui::GetStyle();
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 6.0f;
  style.WindowBorderSize = 1.0f;
  style.WindowPadding = ImVec2(12.0f, 10.0f);
  style.ItemSpacing = ImVec2(8.0f, 4.0f);
  style.CellPadding = ImVec2(6.0f, 1.0f);
  style.Colors[ImGuiCol_WindowBg] = ImVec4(0.05f, 0.06f, 0.08f, 0.78f);
  style.Colors[ImGuiCol_Border] = ImVec4(1.0f, 1.0f, 1.0f, 0.18f);
  style.Colors[ImGuiCol_Separator] = ImVec4(1.0f, 1.0f, 1.0f, 0.22f);
  style.Colors[ImGuiCol_Text] = ImVec4(0.95f, 0.96f, 0.98f, 1.0f);
  style.Colors[ImGuiCol_TableRowBgAlt] = ImVec4(1.0f, 1.0f, 1.0f, 0.05f);
}

}  // namespace

Overlay::Overlay(int width, int height, unsigned target) : width_(width), height_(height), target_(target) {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the videos
  io.LogFilename = nullptr;
  // ~17 px at 720p, scaled with the image; readable in a 1080p video and at 360p.
  const float sizePx = std::clamp(std::round(static_cast<float>(height) * 0.0235f), 11.0f, 48.0f);
  bodyFont_ = loadFont(io, sizePx);
  titleFont_ = loadFont(io, std::round(sizePx * 1.2f));
  labelFont_ = loadFont(io, std::round(sizePx * kLabelFontScale));
  applyStyle();
  ImGui::GetStyle().ScaleAllSizes(std::max(0.75f, sizePx / 17.0f));
  if (!ImGui_ImplOpenGL2_Init()) {
    ImGui::DestroyContext(context_);
    throw RenderError("ImGui: the OpenGL2 backend failed to initialise");
  }
}

Overlay::~Overlay() {
  ImGui::SetCurrentContext(context_);
  ImGui_ImplOpenGL2_Shutdown();
  ImGui::DestroyContext(context_);
}

bool Overlay::draw(const OverlayData& data, float deltaSeconds, const UiFrame* ui) {
  const bool panel = data.panel != PanelMode::Off && !(data.title.empty() && data.caption.empty() && data.rows.empty());
  if (!panel && data.labels.empty() && data.plots.empty() && data.maps.maps.empty() && ui == nullptr) return false;
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
  io.DeltaTime = deltaSeconds > 0.0f ? deltaSeconds : 1.0f / 60.0f;  // ImGui asserts on <= 0
  if (ui != nullptr) {
    io.MousePos = ui->input.mouseX >= 0.0f ? ImVec2(ui->input.mouseX, ui->input.mouseY) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = ui->input.mouseDown[b];
    io.MouseWheel = ui->input.wheel;
  }
  ImGui_ImplOpenGL2_NewFrame();
  ImGui::NewFrame();
  drawLabels(data);
  const float panelBottom = panel ? drawPanel(data) : 0.0f;
  drawPlots(data, panelBottom);
  drawMaps(data);
  if (ui != nullptr && ui->draw) {
    ImGui::PushFont(bodyFont_);
    ui->draw();
    ImGui::PopFont();
  }
  ImGui::Render();

  // The OpenGL2 backend predates shaders and buffer objects: with a program or an array buffer
  // bound, its client-side vertex pointers would be misread. It saves and restores the rest.
  glBindFramebuffer(GL_FRAMEBUFFER, target_);
  glUseProgram(0);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glActiveTexture(GL_TEXTURE0);
  ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
  return io.WantCaptureMouse;
}

void Overlay::drawLabels(const OverlayData& data) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImGuiWindowFlags flags = kFixedPanelFlags;
  ImGui::PushFont(labelFont_);
  for (std::size_t i = 0; i < data.labels.size(); ++i) {
    const OverlayLabel& label = data.labels[i];
    const ImVec2 text = ImGui::CalcTextSize(label.text.c_str());
    const ImVec2 size(text.x + 2.0f * style.WindowPadding.x, text.y + 2.0f * style.WindowPadding.y);
    // Top centre (or top left) on the point, moved inside the image when the point is near its edge.
    const float left = label.leftAligned ? label.pixel.x : label.pixel.x - 0.5f * size.x;
    const float x = std::clamp(left, 0.0f, std::max(0.0f, io.DisplaySize.x - size.x));
    const float y = std::clamp(label.pixel.y, 0.0f, std::max(0.0f, io.DisplaySize.y - size.y));
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(size);  // fixed: see overlay.h
    const std::string id = "##rbsim-label-" + std::to_string(i);
    if (ImGui::Begin(id.c_str(), nullptr, flags)) ImGui::TextColored(kTitleColor, "%s", label.text.c_str());
    ImGui::End();
  }
  ImGui::PopFont();
}

}  // namespace rbsim::render
