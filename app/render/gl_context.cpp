#include "gl_context.h"

#include "egl_context.h"
#include "render_error.h"
#ifdef RBSIM_HAVE_OSMESA
#include "osmesa_context.h"
#endif

namespace rbsim::render {

namespace {
thread_local const GlContext* currentContext = nullptr;
}  // namespace

bool GlContext::isCurrent() const { return currentContext == this; }
void GlContext::markCurrent() const { currentContext = this; }
void GlContext::clearCurrent() const {
  if (currentContext == this) currentContext = nullptr;
}

GlBackend defaultGlBackend() {
#ifdef RBSIM_HAVE_OSMESA
  return GlBackend::Osmesa;
#else
  return GlBackend::Egl;
#endif
}

std::optional<GlBackend> parseGlBackend(const std::string& name) {
#ifdef RBSIM_HAVE_OSMESA
  if (name == "osmesa") return GlBackend::Osmesa;
#endif
  if (name == "egl") return GlBackend::Egl;
  return std::nullopt;
}

const char* glBackendName(GlBackend backend) {
  return backend == GlBackend::Osmesa ? "osmesa" : "egl";
}

std::string glBackendChoices() {
#ifdef RBSIM_HAVE_OSMESA
  return "osmesa|egl";
#else
  return "egl (this build has no OSMesa)";
#endif
}

std::unique_ptr<GlContext> makeGlContext(GlBackend backend, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw RenderError(std::string(glBackendName(backend)) + ": invalid image size " +
                      std::to_string(width) + "x" + std::to_string(height));
  }
#ifdef RBSIM_HAVE_OSMESA
  if (backend == GlBackend::Osmesa) return std::make_unique<OsmesaContext>(width, height);
#endif
  if (backend == GlBackend::Egl) return std::make_unique<EglContext>(width, height);
  throw RenderError(std::string("this build has no ") + glBackendName(backend) + " context");
}

}  // namespace rbsim::render
