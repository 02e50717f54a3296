#include "timing.h"

#include <cstdio>

namespace rbsim::render {

std::string formatTiming(const RenderTiming& render, const SinkTiming& sink) {
  char text[256];
  std::snprintf(text, sizeof text,
                "ms per frame: render %.1f, copy %.1f, encode %.1f (background; png %.1f, "
                "video %.1f, producer blocked %.1f)",
                render.renderMs, render.copyMs, sink.encodeMs, sink.pngMs, sink.videoMs,
                sink.blockedMs);
  return text;
}

}  // namespace rbsim::render
