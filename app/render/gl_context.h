#pragma once
// An off-screen OpenGL 4.5 compatibility-profile context on llvmpipe, whichever way the machine
// offers one: OSMesa (renders into a buffer in main memory; gone from Mesa 25.1 on) or EGL on
// the surfaceless platform (EGL_MESA_platform_surfaceless) drawing into a framebuffer object.
// Both are Mesa contexts on the same shared libglapi dispatch, so the GL entry points this
// library calls reach whichever context is current (DESIGN.md, "Rendering facts").
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace rbsim::render {

enum class GlBackend { Osmesa, Egl };

// OSMesa when the build has it (RBSIM_HAVE_OSMESA), else EGL.
GlBackend defaultGlBackend();
// "osmesa" or "egl"; nullopt for anything else, or for osmesa in a build without it.
std::optional<GlBackend> parseGlBackend(const std::string& name);
const char* glBackendName(GlBackend backend);
// The names parseGlBackend accepts in this build, for help texts and errors.
std::string glBackendChoices();

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes the context current on the calling thread (cheap when it already is).
  virtual void makeCurrent() = 0;
  // The framebuffer that receives the image: 0 for OSMesa, the context's own object for EGL.
  virtual unsigned framebuffer() const = 0;
  // The finished image, RGBA8, bottom row first (GL's origin); call after glFinish(). Valid
  // until the next call.
  virtual const std::uint8_t* pixels() = 0;

  int width() const { return width_; }
  int height() const { return height_; }

 protected:
  GlContext(int width, int height) : width_(width), height_(height) {}
  // Whether this context is the one last made current on this thread by any GlContext: the
  // backends' own "current" queries do not see each other's switches.
  bool isCurrent() const;
  void markCurrent() const;
  void clearCurrent() const;  // after releasing the context, in the destructor

 private:
  int width_;
  int height_;
};

// Creates a width x height context (RGBA8 colour, 24-bit depth, 8-bit stencil) and makes it
// current on this thread. Throws RenderError naming the backend when that is impossible.
std::unique_ptr<GlContext> makeGlContext(GlBackend backend, int width, int height);

}  // namespace rbsim::render
