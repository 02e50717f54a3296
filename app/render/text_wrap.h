#pragma once
// Text measured and wrapped with the font it is drawn in, so that no line is ever cut off
// (issue 38): the overlay panel's rows and the plots' titles.
#include <string>
#include <vector>

#include <imgui.h>

namespace rbsim::render {

// Width of `text` in `font` at `size` [px], or at the font's own size.
float textWidth(const ImFont* font, float size, const std::string& text);
inline float textWidth(const ImFont* font, const std::string& text) { return textWidth(font, font->FontSize, text); }

// `text` in lines at most maxWidth wide: broken at spaces and newlines, and a word wider than a
// line (a path, a long number) between characters. ImGui's own wrapping also breaks after '.'
// and ',', which tears numbers such as "1.5" across two lines.
std::vector<std::string> wrapLines(const ImFont* font, float size, const std::string& text, float maxWidth);
inline std::vector<std::string> wrapLines(const ImFont* font, const std::string& text, float maxWidth) {
  return wrapLines(font, font->FontSize, text, maxWidth);
}

}  // namespace rbsim::render
