#include "run/compare_view.h"

#include <algorithm>

#include <glm/glm.hpp>

#include "render/pane_layout.h"
#include "run/frame_builder.h"

namespace rbsim::app {

namespace {

// buildFrame's overlay starts with "time t" and "integrator"; a comparison's rows follow them.
constexpr std::ptrdiff_t kLeadingRows = 2;

// A pane's caption: its top left corner this far inside the pane's [px of a 720-row image].
constexpr float kCaptionInset = 10.0f;
constexpr float kReferenceRows = 720.0f;

// The selected body in every world, quantity by quantity, so the values stand one under the
// other: "x  PGS", "x  soft step", "v  PGS", ... (KE: kinetic energy, a short label keeps the
// panel narrow enough to leave the worlds in view)
// In a compact panel: what is compared, and the error against the exact spin when the phase
// measures it, else the spin and the energy of each world.
std::vector<render::OverlayRow> selectedBodyRows(const std::vector<World>& worlds, const Phase& phase,
                                                 const std::vector<FreeFlightError>* freeFlight) {
  using render::RowLevel;
  const Scene& scene = phase.scene();
  const std::size_t i = scene.view.selected;
  std::vector<render::OverlayRow> rows = {{"compared", phase.compareKey, RowLevel::Essential}};
  if (i >= worlds.front().bodies().size()) return rows;  // a scene of particles alone has no bodies
  const RigidBody& body = worlds.front().bodies()[i];
  rows.push_back({"body", body.name() + " (" + scene.inertiaMethods[i] + " inertia, " + formatNumber(body.mass(), "kg") + ")", RowLevel::Useful});
  const auto add = [&](const char* name, RowLevel level, auto value) {
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      if (i < worlds[k].bodies().size()) rows.push_back({std::string(name) + "  " + phase.worlds[k].label, value(worlds[k].bodies()[i]), level});
    }
  };
  const bool measured = freeFlight != nullptr;
  add("x", RowLevel::Detail, [](const RigidBody& b) { return formatVec(b.position(), "m"); });
  add("v", RowLevel::Detail, [](const RigidBody& b) { return formatVec(b.velocity(), "m/s"); });
  add("omega", measured ? RowLevel::Detail : RowLevel::Useful, [](const RigidBody& b) { return formatVec(b.angularVelocity(), "rad/s"); });
  add("KE", measured ? RowLevel::Detail : RowLevel::Useful,
      [](const RigidBody& b) { return formatNumber(b.kineticEnergy(), b.awake() ? "J" : "J (asleep)"); });
  if (measured) {
    for (std::size_t k = 0; k < worlds.size() && k < freeFlight->size(); ++k) {
      rows.push_back({"vs exact spin  " + phase.worlds[k].label, freeFlightRow((*freeFlight)[k], worlds[k]), RowLevel::Essential});
    }
  }
  return rows;
}

}  // namespace

render::FrameData buildPhaseFrame(const std::vector<World>& worlds, const Phase& phase, const std::string& demoTitle,
                                  const std::vector<FreeFlightError>* freeFlight) {
  const FreeFlightError* first = freeFlight != nullptr && !freeFlight->empty() ? &freeFlight->front() : nullptr;
  const ViewDesc& view = phase.scene().view;
  const bool panel = view.overlay && view.panel != ViewDesc::Panel::Off;
  if (!phase.compared()) {
    render::FrameData frame = buildFrame(worlds.front(), phase.scene(), demoTitle, true, first);
    placeBesidePanel(frame, view);
    return frame;
  }
  // The panel and the plots in a column of their own, each world in a pane (pane_layout.h).
  render::FrameData frame = buildFrame(worlds.front(), phase.scene(), demoTitle, /*selectedBodyRows=*/false);
  frame.infoColumn = panel || !view.plots.empty();
  frame.overlay.plotsUnderPanel = frame.infoColumn;
  const std::vector<render::PaneRect> rects =
      render::paneLayout(worlds.size(), view.width, view.height, frame.infoColumn, frame.overlay.panel);
  const float inset = kCaptionInset * static_cast<float>(view.height) / kReferenceRows;
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    render::FrameData pane = buildFrame(worlds[k], phase.worlds[k].scene, demoTitle);
    if (k > 0) {
      for (render::BodyView& body : pane.bodies) body.selected = false;  // the panel follows world 0
    }
    pane.camera = render::paneCamera(pane.camera, view.width, view.height, rects[k]);
    pane.overlay = render::OverlayData{};
    frame.panes.push_back(std::move(pane));
    // At the pane's top left, where the sky usually is, clear of what the camera looks at.
    const glm::vec2 corner(static_cast<float>(rects[k].x) + inset, static_cast<float>(rects[k].y) + inset);
    frame.overlay.labels.push_back({phase.worlds[k].label, corner, /*leftAligned=*/true});
  }
  frame.bodies.clear();
  frame.forces.clear();
  frame.lines.clear();
  frame.points.clear();
  frame.sprites.clear();
  // After "time t" and "integrator" (buildFrame's first rows), before any debug view's rows.
  const std::vector<render::OverlayRow> rows = selectedBodyRows(worlds, phase, freeFlight);
  auto& all = frame.overlay.rows;
  all.insert(all.begin() + std::min<std::ptrdiff_t>(kLeadingRows, static_cast<std::ptrdiff_t>(all.size())), rows.begin(), rows.end());
  return frame;
}

}  // namespace rbsim::app
