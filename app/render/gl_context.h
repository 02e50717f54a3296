#pragma once
// An off-screen OpenGL 4.5 compatibility-profile context on llvmpipe, whichever way the machine
// offers one: OSMesa (renders into a buffer in main memory; gone from Mesa 25.1 on) or EGL on
// the surfaceless platform (EGL_MESA_platform_surfaceless) drawing into a framebuffer object.
// Both are Mesa contexts on the same shared libglapi dispatch (libOSMesa links libglapi.so.0, as
// EGL's driver does), so the GL entry points this library links from libOSMesa reach whichever
// context is current; tests/render/gl_backend_test.cpp draws through both in one process. Both draw
// into a framebuffer object of the context's own, never OSMesa's window-system buffer: that one
// is stored upside down, so a copy between it and an object (the renderer's cached background)
// would need a draw call instead of a memory copy, and the two backends would round edge pixels
// differently.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>
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
  // The framebuffer object that receives the image (RGBA8, 24-bit depth, 8-bit stencil).
  unsigned framebuffer() const { return fbo_; }
  // Reads the finished image into `out` (width*height*4 bytes, RGBA8, top row first); call with
  // the context current. GL_MESA_pack_invert has glReadPixels write the rows top first, so the
  // image is copied once; without it, it is read and then flipped row by row.
  void readTopDown(std::uint8_t* out);

  int width() const { return width_; }
  int height() const { return height_; }

 protected:
  GlContext(int width, int height) : width_(width), height_(height) {}
  // Whether this context is the one last made current on this thread by any GlContext: the
  // backends' own "current" queries do not see each other's switches.
  bool isCurrent() const;
  void markCurrent() const;
  void clearCurrent() const;  // after releasing the context, in the destructor
  // With the new context current: the framebuffer object. Throws RenderError naming `backend`
  // if the size is over the driver's limit or the object is incomplete.
  void createFramebuffer(const char* backend);
  // With the context current, before it is destroyed.
  void deleteFramebuffer();

 private:
  int width_;
  int height_;
  unsigned fbo_ = 0, colorRb_ = 0, depthRb_ = 0;
  bool packInvert_ = false;           // GL_MESA_pack_invert is offered
  std::vector<std::uint8_t> buffer_;  // bottom row first, when it is not
};

// Creates a width x height context (RGBA8 colour, 24-bit depth, 8-bit stencil) and makes it
// current on this thread. Throws RenderError naming the backend when that is impossible.
std::unique_ptr<GlContext> makeGlContext(GlBackend backend, int width, int height);

}  // namespace rbsim::render
