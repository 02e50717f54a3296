#pragma once
// Where the overlay panel's text goes (issue 38): the panel's box and every line in it, measured
// with the fonts it is drawn with, so that nothing is ever cut off. A value too wide for the room
// beside its label goes on the line below it, wrapped at spaces; a row too long for the image is
// left out with the rows after it, the least important first, and a last line says how many.
#include <cstddef>
#include <string>
#include <vector>

#include "frame_data.h"

namespace rbsim::render {

struct PanelLine {
  std::string text;
  float x = 0.0f, y = 0.0f;  // its top left, in pixels from the image's top left
  float width = 0.0f;        // measured [px]
  float height = 0.0f;       // its font's line height [px]
  enum class Kind { Title, Caption, Label, Value, More } kind = Kind::Value;
};

struct PanelLayout {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;  // the panel's box [px]; width 0: no panel
  float innerLeft = 0.0f, innerRight = 0.0f;              // where text may go [px]
  std::vector<PanelLine> lines;
  std::vector<float> rowTops, rowBottoms;  // each shown row's band, for the alternating shade [px]
  std::size_t shownRows = 0, hiddenRows = 0;
};

}  // namespace rbsim::render
