#pragma once
// A plain X11 window that shows the images the off-screen renderer makes (docs/architecture.md "Rendering
// facts": libOSMesa exports the GL entry points itself, and linking libGL for a GLX window into
// the same process clashes with it). So the window has no GL context at all: the OSMesa image is
// copied to it with XPutImage, and the window only reports the pointer and the keys. What the
// window shows is, by construction, what the off-screen path writes to PNG.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rbsim::app {

// No X display (DISPLAY unset or unreachable), or one without a 24/32-bit TrueColor visual.
class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What happened since the last poll.
struct WindowInput {
  int mouseX = -1, mouseY = -1;       // [px] from the top left; -1 when the pointer left
  bool down[3] = {false, false, false};  // left, right, middle, as they are now
  bool pressed[3] = {false, false, false};  // went down during this poll
  float wheel = 0.0f;                 // notches, + away from the user
  std::string keys;                   // printable keys typed, in order; '\x1b' for Escape
  bool closed = false;                // the window manager asked to close the window
};

class X11Window {
 public:
  // Opens a window of the image's size on $DISPLAY and waits until it is mapped.
  X11Window(int width, int height, const std::string& title);
  ~X11Window();
  X11Window(const X11Window&) = delete;
  X11Window& operator=(const X11Window&) = delete;

  // Drains the pending events into `input` (down[] and the pointer persist between polls).
  void poll(WindowInput& input);
  // Shows an RGBA image, top row first, width*height*4 bytes.
  void present(const std::vector<std::uint8_t>& rgba);
  // What the X server holds for the window now, RGBA top row first (a screenshot).
  std::vector<std::uint8_t> capture() const;
  // Offers `text` as the CLIPBOARD and PRIMARY selections (ICCCM section 2): other programs paste
  // it while the window is open; poll() answers their requests.
  void setClipboard(const std::string& text);

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_;
  int height_;
};

}  // namespace rbsim::app
