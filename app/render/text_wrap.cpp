#include "text_wrap.h"

#include <cfloat>

namespace rbsim::render {

namespace {

// The longest prefix of `word` (at a UTF-8 character boundary, at least one character) that is at
// most maxWidth wide.
std::size_t fittingPrefix(const ImFont* font, float size, const std::string& word, float maxWidth) {
  std::size_t end = 0, best = 0;
  while (end < word.size()) {
    std::size_t next = end + 1;
    while (next < word.size() && (static_cast<unsigned char>(word[next]) & 0xC0) == 0x80) ++next;
    if (best > 0 && textWidth(font, size, word.substr(0, next)) > maxWidth) break;
    best = end = next;
  }
  return best;
}

}  // namespace

float textWidth(const ImFont* font, float size, const std::string& text) {
  return font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str()).x;
}

std::vector<std::string> wrapLines(const ImFont* font, float size, const std::string& text, float maxWidth) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find_first_of(" \n", start);
    if (end == std::string::npos) end = text.size();
    std::string word = text.substr(start, end - start);
    while (true) {
      const std::string candidate = line.empty() ? word : line + " " + word;
      if (textWidth(font, size, candidate) <= maxWidth) {
        line = candidate;
        break;
      }
      if (!line.empty()) {
        lines.push_back(line);
        line.clear();
        continue;
      }
      const std::size_t cut = fittingPrefix(font, size, word, maxWidth);
      lines.push_back(word.substr(0, cut));
      word = word.substr(cut);
      if (word.empty()) break;
    }
    if (end < text.size() && text[end] == '\n') {
      lines.push_back(line);
      line.clear();
    }
    start = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

}  // namespace rbsim::render
