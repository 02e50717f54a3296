#pragma once
// Full-frame title cards for a reel of demos: a dark backdrop with a large title, a description
// and a list (a demo's phases, or the reel's demos), drawn by our own renderer (ImGui text on an
// GL context of its own), not by an ffmpeg filter. Not thread-safe, like OffscreenRenderer.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl_context.h"

namespace rbsim::render {

struct TitleCard {
  std::string kicker;       // small capitals above the title, e.g. "DEMO 3 OF 6"
  std::string number;       // large, in the accent colour, before the title (may be empty)
  std::string title;        // the large line
  std::string description;  // wrapped below the title
  std::string listHeading;  // e.g. "Phases"; the list is left out when `list` is empty
  struct Row {
    // e.g. "1", "particles", "fountain, fire and smoke", "24.0 s"; `detail` is dim, after `text`,
    // and cut short with "..." where the line would reach `right`.
    std::string number, text, detail, right;
  };
  std::vector<Row> list;
  std::string footerLeft, footerRight;  // small, dim, at the bottom corners
};

class TitleCardRenderer {
 public:
  // Makes its own GL context (OffscreenRenderer's stays untouched; each makes its own
  // current before drawing). Throws RenderError like OffscreenRenderer.
  TitleCardRenderer(int width, int height, GlBackend backend = defaultGlBackend());
  ~TitleCardRenderer();
  TitleCardRenderer(const TitleCardRenderer&) = delete;
  TitleCardRenderer& operator=(const TitleCardRenderer&) = delete;

  // The card as width*height*4 bytes, RGBA, top row first; valid until the next call.
  const std::vector<std::uint8_t>& render(const TitleCard& card);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rbsim::render
