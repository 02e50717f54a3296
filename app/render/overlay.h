#pragma once
// The text panel drawn over the 3D image: Dear ImGui (Debian's 1.86) with its OpenGL2 backend
// and no platform backend (there is no window and no input; we set display size and time step).
#include "frame_data.h"
#include "panel_layout.h"
#include "ui_frame.h"

struct ImGuiContext;
struct ImFont;

namespace rbsim::render {

class Overlay {
 public:
  // Needs a current GL compatibility context. Font size follows the image height; DejaVu Sans
  // Mono is used when installed (monospace, so number columns line up), else ImGui's own font.
  Overlay(int width, int height, unsigned target);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // Draws a fixed-size, fixed-position panel at the top left into `target` (none when
  // `data` has no title, caption or rows), and each of data.labels in a box of its own. Fixed
  // size, because ImGui hides an auto-sized window on its first frame (docs/architecture.md, "Rendering facts"). With `ui`, its pointer drives ImGui and its windows are drawn in the same frame;
  // returns whether ImGui wants the pointer (it is over a control). Leaves no program, vertex
  // array or buffer bound; the GL renderer sets everything else it needs each frame.
  bool draw(const OverlayData& data, float deltaSeconds, const UiFrame* ui = nullptr);
  // Where the panel of `data` goes and every line of its text, as draw() lays it out (tests
  // check that no text leaves its box). Needs the context current, like draw().
  PanelLayout layoutPanel(const OverlayData& data);

 private:
  // Inside an ImGui frame (panel_draw.cpp); returns the panel's bottom edge [px from the top], 0
  // with no panel.
  float drawPanel(const OverlayData& data);
  PanelLayout panelLayout(const OverlayData& data) const;  // inside an ImGui frame
  // The least height the plots under the panel need, with their margin (plot_panel.cpp) [px].
  float leastPlotsHeight(const OverlayData& data) const;
  void drawLabels(const OverlayData& data);  // inside an ImGui frame
  // Inside an ImGui frame (plot_panel.cpp); `top` is where plots under the panel may start [px].
  void drawPlots(const OverlayData& data, float top);
  // Inside an ImGui frame (slice_panel.cpp): data.maps in its column at the right.
  void drawMaps(const OverlayData& data);

  int width_;
  int height_;
  unsigned target_;  // the context's framebuffer
  ImGuiContext* context_ = nullptr;
  ImFont* bodyFont_ = nullptr;
  ImFont* titleFont_ = nullptr;
  ImFont* labelFont_ = nullptr;
};

}  // namespace rbsim::render
