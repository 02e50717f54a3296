#include "title_card.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include "gl_api.h"
#include "gl_context.h"
#include "render_error.h"
#include "text_wrap.h"

namespace rbsim::render {

namespace {

constexpr const char* kFontDir = "/usr/share/fonts/truetype/dejavu/";

// The layout is drawn for 720 rows and scaled with the image height; sizes in pixels at 720p.
constexpr float kDesignHeight = 720.0f;
constexpr float kTitlePx = 80.0f, kKickerPx = 22.0f, kBodyPx = 27.0f, kRowPx = 23.0f, kFooterPx = 17.0f;
constexpr float kMarginPx = 120.0f;  // left and right text margin

// The overlay's amber title colour, so cards and demo frames read as one piece.
const ImU32 kAccent = IM_COL32(255, 209, 89, 255);
const ImU32 kWhite = IM_COL32(242, 245, 250, 255);
const ImU32 kSoft = IM_COL32(199, 209, 224, 255);
const ImU32 kDim = IM_COL32(130, 140, 156, 255);
const ImU32 kRule = IM_COL32(255, 255, 255, 28);
const ImU32 kTop = IM_COL32(20, 26, 36, 255);
const ImU32 kBottom = IM_COL32(6, 8, 12, 255);

ImFont* loadFont(ImGuiIO& io, const char* file, float sizePx) {
  const std::string path = std::string(kFontDir) + file;
  if (std::filesystem::exists(path)) {
    ImFontConfig config;
    config.OversampleH = 2;
    if (ImFont* font = io.Fonts->AddFontFromFileTTF(path.c_str(), sizePx, &config)) return font;
  }
  ImFontConfig config;  // ImGui's own 13 px font, in whole steps to keep it crisp
  config.SizePixels = 13.0f * std::max(1.0f, std::round(sizePx / 13.0f));
  return io.Fonts->AddFontDefault(&config);
}

// The text, or its longest prefix ending at a word that fits with "..." after it.
std::string fitWidth(const ImFont* font, float size, const std::string& text, float maxWidth) {
  if (textWidth(font, size, text) <= maxWidth) return text;
  std::string cut = text;
  while (!cut.empty()) {
    const std::size_t space = cut.rfind(' ');
    cut = space == std::string::npos ? std::string() : cut.substr(0, space);
    while (!cut.empty() && (cut.back() == ',' || cut.back() == ':')) cut.pop_back();
    if (textWidth(font, size, cut + "...") <= maxWidth) return cut + "...";
  }
  return "";
}

// Small capitals look set, not typed, with a little space between letters.
void drawTracked(ImDrawList* list, const ImFont* font, float size, ImVec2 at, ImU32 colour, const std::string& text,
                 float tracking) {
  for (std::size_t i = 0; i < text.size();) {
    std::size_t length = 1;  // one UTF-8 character: a lead byte and its continuation bytes
    while (i + length < text.size() && (static_cast<unsigned char>(text[i + length]) & 0xC0) == 0x80) ++length;
    const std::string glyph = text.substr(i, length);
    list->AddText(font, size, at, colour, glyph.c_str());
    at.x += textWidth(font, size, glyph) + tracking;
    i += length;
  }
}

}  // namespace

struct TitleCardRenderer::Impl {
  std::unique_ptr<GlContext> context;
  ImGuiContext* imgui = nullptr;
  float scale = 1.0f;
  ImFont* title = nullptr;
  ImFont* kicker = nullptr;
  ImFont* body = nullptr;
  ImFont* row = nullptr;
  ImFont* mono = nullptr;
  ImFont* footer = nullptr;
  std::vector<std::uint8_t> image;

  Impl(int width, int height, GlBackend backend)
      : context(makeGlContext(backend, width, height)), image(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    scale = static_cast<float>(height) / kDesignHeight;
    imgui = ImGui::CreateContext();
    ImGui::SetCurrentContext(imgui);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    title = loadFont(io, "DejaVuSans-Bold.ttf", std::round(kTitlePx * scale));
    kicker = loadFont(io, "DejaVuSans-Bold.ttf", std::round(kKickerPx * scale));
    body = loadFont(io, "DejaVuSans.ttf", std::round(kBodyPx * scale));
    row = loadFont(io, "DejaVuSans.ttf", std::round(kRowPx * scale));
    mono = loadFont(io, "DejaVuSansMono.ttf", std::round(kRowPx * scale));
    footer = loadFont(io, "DejaVuSans.ttf", std::round(kFooterPx * scale));
    if (!ImGui_ImplOpenGL2_Init()) {
      ImGui::DestroyContext(imgui);
      throw RenderError("ImGui: the OpenGL2 backend failed to initialise (title cards)");
    }
  }

  ~Impl() {
    context->makeCurrent();
    ImGui::SetCurrentContext(imgui);
    ImGui_ImplOpenGL2_Shutdown();
    ImGui::DestroyContext(imgui);
  }

  void layout(const TitleCard& card, ImDrawList* list) const;
};

void TitleCardRenderer::Impl::layout(const TitleCard& card, ImDrawList* list) const {
  const float width = static_cast<float>(context->width()), height = static_cast<float>(context->height());
  const float s = scale;
  const float left = kMarginPx * s, right = width - kMarginPx * s;
  list->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(width, height), kTop, kTop, kBottom, kBottom);

  // A long title is set smaller rather than run into the margin.
  const float titleWidth = textWidth(title, title->FontSize, card.number.empty() ? card.title : card.number + "  " + card.title);
  const float titleSize = std::round(title->FontSize * std::min(1.0f, (right - left) / titleWidth));
  const float bodySize = body->FontSize, rowSize = row->FontSize;
  const std::vector<std::string> description = wrapLines(body, bodySize, card.description, right - left);
  const float rowHeight = rowSize * 1.75f;
  // Height of the whole block, to centre it vertically (a card with one phase and the opening
  // card with every demo both sit balanced).
  float block = kicker->FontSize + 14.0f * s + titleSize + 26.0f * s + 4.0f * s + 26.0f * s;
  block += static_cast<float>(description.size()) * bodySize * 1.35f;
  if (!card.list.empty()) block += 40.0f * s + kicker->FontSize + 14.0f * s + rowHeight * static_cast<float>(card.list.size());
  float y = std::round(std::max(60.0f * s, 0.5f * (height - block) - 20.0f * s));

  drawTracked(list, kicker, kicker->FontSize, ImVec2(left, y), kAccent, card.kicker, 3.0f * s);
  y += kicker->FontSize + 14.0f * s;
  float titleX = left - 4.0f * s;  // the bold face's side bearing, so the title lines up optically
  if (!card.number.empty()) {
    list->AddText(title, titleSize, ImVec2(titleX, y), kAccent, card.number.c_str());
    titleX += textWidth(title, titleSize, card.number) + 0.45f * titleSize;
  }
  list->AddText(title, titleSize, ImVec2(titleX, y), kWhite, card.title.c_str());
  y += titleSize + 26.0f * s;
  list->AddRectFilled(ImVec2(left, y), ImVec2(left + 96.0f * s, y + 4.0f * s), kAccent);
  y += 4.0f * s + 26.0f * s;
  for (const std::string& line : description) {
    list->AddText(body, bodySize, ImVec2(left, y), kSoft, line.c_str());
    y += bodySize * 1.35f;
  }

  if (!card.list.empty()) {
    y += 40.0f * s;
    drawTracked(list, kicker, kicker->FontSize, ImVec2(left, y), kDim, card.listHeading, 3.0f * s);
    y += kicker->FontSize + 14.0f * s;
    float numberWidth = 0.0f;
    for (const TitleCard::Row& r : card.list) numberWidth = std::max(numberWidth, textWidth(mono, rowSize, r.number));
    for (const TitleCard::Row& r : card.list) {
      list->AddLine(ImVec2(left, y), ImVec2(right, y), kRule, std::max(1.0f, s));
      const float baseline = y + 0.5f * (rowHeight - rowSize);
      list->AddText(mono, rowSize, ImVec2(left + numberWidth - textWidth(mono, rowSize, r.number), baseline), kAccent,
                    r.number.c_str());
      const float textX = left + numberWidth + 28.0f * s;
      list->AddText(row, rowSize, ImVec2(textX, baseline), kWhite, r.text.c_str());
      if (!r.detail.empty()) {
        const float detailX = textX + textWidth(row, rowSize, r.text) + 0.6f * rowSize;
        const float room = right - textWidth(mono, rowSize, r.right) - 2.0f * rowSize - detailX;
        list->AddText(row, rowSize, ImVec2(detailX, baseline), kDim, fitWidth(row, rowSize, r.detail, room).c_str());
      }
      list->AddText(mono, rowSize, ImVec2(right - textWidth(mono, rowSize, r.right), baseline), kDim, r.right.c_str());
      y += rowHeight;
    }
    list->AddLine(ImVec2(left, y), ImVec2(right, y), kRule, std::max(1.0f, s));
  }

  const float footerY = height - 44.0f * s - footer->FontSize;
  list->AddText(footer, footer->FontSize, ImVec2(left, footerY), kDim, card.footerLeft.c_str());
  list->AddText(footer, footer->FontSize, ImVec2(right - textWidth(footer, footer->FontSize, card.footerRight), footerY),
                kDim, card.footerRight.c_str());
}

TitleCardRenderer::TitleCardRenderer(int width, int height, GlBackend backend)
    : impl_(std::make_unique<Impl>(width, height, backend)) {}

TitleCardRenderer::~TitleCardRenderer() = default;

const std::vector<std::uint8_t>& TitleCardRenderer::render(const TitleCard& card) {
  Impl& d = *impl_;
  d.context->makeCurrent();
  ImGui::SetCurrentContext(d.imgui);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(d.context->width()), static_cast<float>(d.context->height()));
  io.DeltaTime = 1.0f / 60.0f;  // no animation; ImGui only needs it positive
  ImGui_ImplOpenGL2_NewFrame();
  ImGui::NewFrame();
  d.layout(card, ImGui::GetBackgroundDrawList());
  ImGui::Render();

  glBindFramebuffer(GL_FRAMEBUFFER, d.context->framebuffer());
  glViewport(0, 0, d.context->width(), d.context->height());
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw RenderError("OpenGL error while rendering a title card");
  }

  d.context->readTopDown(d.image.data());
  return d.image;
}

}  // namespace rbsim::render
