#include "window/x11_window.h"

// Xlib's macros (None, Bool, Status) stay inside this file.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/Xatom.h>
#include <X11/keysym.h>

#include <cstdlib>
#include <string>

namespace rbsim::app {

namespace {

// Position of a channel mask's lowest bit, so that any 8-bit-per-channel TrueColor layout works.
int shiftOf(unsigned long mask) {
  int shift = 0;
  while (mask != 0 && (mask & 1ul) == 0) {
    mask >>= 1;
    ++shift;
  }
  return shift;
}

}  // namespace

struct X11Window::Impl {
  Display* display = nullptr;
  Window window = 0;
  Atom deleteMessage = 0;
  XVisualInfo visual{};
  XImage* image = nullptr;  // owns `pixels` (XDestroyImage frees it)
  int redShift = 0, greenShift = 0, blueShift = 0;
  bool releaseNext[3] = {false, false, false};
  Atom clipboard = 0, utf8 = 0, targets = 0;
  std::string selection;  // what setClipboard offers; empty: nothing

  // Another client asks for the selection as `request.target`: the text, or the list of the
  // targets it can be had as, written to the requestor's property (ICCCM 2.2).
  void answer(const XSelectionRequestEvent& request) {
    XSelectionEvent reply{};
    reply.type = SelectionNotify;
    reply.display = request.display;
    reply.requestor = request.requestor;
    reply.selection = request.selection;
    reply.target = request.target;
    reply.time = request.time;
    reply.property = None;
    const Atom property = request.property != None ? request.property : request.target;  // obsolete clients
    if (!selection.empty() && request.target == targets) {
      const Atom offered[] = {targets, utf8, XA_STRING};
      XChangeProperty(display, request.requestor, property, XA_ATOM, 32, PropModeReplace,
                      reinterpret_cast<const unsigned char*>(offered), 3);
      reply.property = property;
    } else if (!selection.empty() && (request.target == utf8 || request.target == XA_STRING)) {
      XChangeProperty(display, request.requestor, property, request.target, 8, PropModeReplace,
                      reinterpret_cast<const unsigned char*>(selection.data()), static_cast<int>(selection.size()));
      reply.property = property;
    }
    XSendEvent(display, request.requestor, False, 0, reinterpret_cast<XEvent*>(&reply));
  }
};

X11Window::X11Window(int width, int height, const std::string& title)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
  Impl& d = *impl_;
  d.display = XOpenDisplay(nullptr);
  if (d.display == nullptr) {
    throw WindowError("cannot open the X display (DISPLAY is unset or unreachable); --window needs an X server, e.g. xvfb-run");
  }
  const int screen = DefaultScreen(d.display);
  if (!XMatchVisualInfo(d.display, screen, 24, TrueColor, &d.visual) &&
      !XMatchVisualInfo(d.display, screen, 32, TrueColor, &d.visual)) {
    XCloseDisplay(d.display);
    throw WindowError("the X display has no 24-bit TrueColor visual (for Xvfb use -screen 0 1920x1080x24)");
  }
  XSetWindowAttributes attributes{};
  attributes.colormap = XCreateColormap(d.display, RootWindow(d.display, screen), d.visual.visual, AllocNone);
  attributes.background_pixel = 0;
  attributes.border_pixel = 0;
  attributes.event_mask = ExposureMask | KeyPressMask | ButtonPressMask | ButtonReleaseMask | PointerMotionMask |
                          LeaveWindowMask | StructureNotifyMask;
  d.window = XCreateWindow(d.display, RootWindow(d.display, screen), 0, 0, static_cast<unsigned>(width),
                           static_cast<unsigned>(height), 0, d.visual.depth, InputOutput, d.visual.visual,
                           CWColormap | CWBackPixel | CWBorderPixel | CWEventMask, &attributes);
  XStoreName(d.display, d.window, title.c_str());
  // A fixed size: the image is rendered at the scene's size, pixel for pixel.
  XSizeHints* hints = XAllocSizeHints();
  hints->flags = PMinSize | PMaxSize;
  hints->min_width = hints->max_width = width;
  hints->min_height = hints->max_height = height;
  XSetWMNormalHints(d.display, d.window, hints);
  XFree(hints);
  d.deleteMessage = XInternAtom(d.display, "WM_DELETE_WINDOW", False);
  d.clipboard = XInternAtom(d.display, "CLIPBOARD", False);
  d.utf8 = XInternAtom(d.display, "UTF8_STRING", False);
  d.targets = XInternAtom(d.display, "TARGETS", False);
  XSetWMProtocols(d.display, d.window, &d.deleteMessage, 1);
  XMapWindow(d.display, d.window);
  XEvent event;
  do {
    XWindowEvent(d.display, d.window, StructureNotifyMask, &event);
  } while (event.type != MapNotify);

  d.redShift = shiftOf(d.visual.red_mask);
  d.greenShift = shiftOf(d.visual.green_mask);
  d.blueShift = shiftOf(d.visual.blue_mask);
  auto* pixels = static_cast<char*>(std::malloc(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4));
  d.image = XCreateImage(d.display, d.visual.visual, static_cast<unsigned>(d.visual.depth), ZPixmap, 0, pixels,
                         static_cast<unsigned>(width), static_cast<unsigned>(height), 32, 0);
  if (d.image == nullptr || d.image->bits_per_pixel != 32) {
    if (d.image != nullptr) XDestroyImage(d.image);
    XDestroyWindow(d.display, d.window);
    XCloseDisplay(d.display);
    throw WindowError("the X display cannot take 32-bit pixels for a 24-bit visual");
  }
}

X11Window::~X11Window() {
  Impl& d = *impl_;
  XDestroyImage(d.image);
  XDestroyWindow(d.display, d.window);
  XCloseDisplay(d.display);
}

void X11Window::poll(WindowInput& input) {
  Impl& d = *impl_;
  // A click whose press and release arrive in one poll is shown down for one frame, so that
  // ImGui (which reads button levels once per frame) still sees the click.
  for (int b = 0; b < 3; ++b) {
    if (d.releaseNext[b]) input.down[b] = false;
    d.releaseNext[b] = false;
  }
  for (bool& p : input.pressed) p = false;
  input.wheel = 0.0f;
  input.keys.clear();
  while (XPending(d.display) > 0) {
    XEvent event;
    XNextEvent(d.display, &event);
    switch (event.type) {
      case MotionNotify:
        input.mouseX = event.xmotion.x;
        input.mouseY = event.xmotion.y;
        break;
      case LeaveNotify:
        input.mouseX = input.mouseY = -1;
        break;
      case ButtonPress:
      case ButtonRelease: {
        const bool down = event.type == ButtonPress;
        input.mouseX = event.xbutton.x;
        input.mouseY = event.xbutton.y;
        // X numbers left, middle, right as 1, 2, 3 and the wheel as 4 (up) and 5 (down).
        const unsigned button = event.xbutton.button;
        if (button >= 4 && button <= 5) {
          if (down) input.wheel += button == 4 ? 1.0f : -1.0f;
          break;
        }
        const int index = button == 1 ? 0 : button == 3 ? 1 : button == 2 ? 2 : -1;
        if (index < 0) break;
        if (down) {
          input.down[index] = true;
          input.pressed[index] = true;
        } else if (input.pressed[index]) {
          d.releaseNext[index] = true;
        } else {
          input.down[index] = false;
        }
        break;
      }
      case KeyPress: {
        char text[8] = {};
        KeySym key = 0;
        const int length = XLookupString(&event.xkey, text, sizeof text, &key, nullptr);
        if (key == XK_Escape) {
          input.keys += '\x1b';
        } else if (length == 1) {
          input.keys += text[0];
        }
        break;
      }
      case ClientMessage:
        if (static_cast<Atom>(event.xclient.data.l[0]) == d.deleteMessage) input.closed = true;
        break;
      case SelectionRequest:
        d.answer(event.xselectionrequest);
        break;
      case SelectionClear:  // another program took the clipboard
        if (event.xselectionclear.selection == d.clipboard) d.selection.clear();
        break;
      default:
        break;
    }
  }
}

void X11Window::present(const std::vector<std::uint8_t>& rgba) {
  Impl& d = *impl_;
  auto* out = reinterpret_cast<std::uint32_t*>(d.image->data);
  const std::size_t count = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* p = &rgba[4 * i];
    out[i] = (static_cast<std::uint32_t>(p[0]) << d.redShift) | (static_cast<std::uint32_t>(p[1]) << d.greenShift) |
             (static_cast<std::uint32_t>(p[2]) << d.blueShift);
  }
  XPutImage(d.display, d.window, DefaultGC(d.display, DefaultScreen(d.display)), d.image, 0, 0, 0, 0,
            static_cast<unsigned>(width_), static_cast<unsigned>(height_));
  XSync(d.display, False);  // the frame is on screen before the next one is simulated
}

void X11Window::setClipboard(const std::string& text) {
  Impl& d = *impl_;
  d.selection = text;
  XSetSelectionOwner(d.display, d.clipboard, d.window, CurrentTime);
  XSetSelectionOwner(d.display, XA_PRIMARY, d.window, CurrentTime);
  XFlush(d.display);
}

std::vector<std::uint8_t> X11Window::capture() const {
  const Impl& d = *impl_;
  XImage* shot = XGetImage(d.display, d.window, 0, 0, static_cast<unsigned>(width_), static_cast<unsigned>(height_),
                           AllPlanes, ZPixmap);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4);
  if (shot == nullptr) throw WindowError("XGetImage could not read the window back");
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const unsigned long pixel = XGetPixel(shot, x, y);
      std::uint8_t* out = &rgba[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x))];
      out[0] = static_cast<std::uint8_t>((pixel & d.visual.red_mask) >> d.redShift);
      out[1] = static_cast<std::uint8_t>((pixel & d.visual.green_mask) >> d.greenShift);
      out[2] = static_cast<std::uint8_t>((pixel & d.visual.blue_mask) >> d.blueShift);
      out[3] = 255;
    }
  }
  XDestroyImage(shot);
  return rgba;
}

}  // namespace rbsim::app
