#pragma once
// World + view description -> the renderer's FrameData: world vertices as the engine computed
// them, body axes, active force arrows, and the overlay's variable table (seed 004 optional
// "visualisation of variables").
#include <optional>
#include <string>

#include "render/frame_data.h"
#include "render/pane_layout.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/free_flight_error.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

render::Camera sceneCamera(const ViewDesc& view);
render::PanelMode panelMode(ViewDesc::Panel panel);

// `selectedBodyRows` false leaves the selected body's variables out of the overlay's rows (a
// compared phase, compare_view.h, shows its own rows of every world instead). With
// `freeFlight` (following the selected body) the rows end with its error against the exact
// torque-free motion.
render::FrameData buildFrame(const World& world, const Scene& scene, const std::string& demoTitle,
                             bool selectedBodyRows = true, const FreeFlightError* freeFlight = nullptr);

// Where a scene alone is drawn when its panel or plots show: a pane right of the info column
// (pane_layout.h), so that the panel and the plots never cover the bodies (issue 38); nullopt when
// the scene has the whole image.
std::optional<render::PaneRect> scenePane(const ViewDesc& view);
// The scene's camera, moved with the selected body under view.follow.
render::Camera viewCamera(const World& world, const ViewDesc& view);
// The scene's own fields of `frame` (built by buildFrame) moved into scenePane(view), seen
// through the pane's camera (render::paneCamera); nothing changes without a pane.
void placeBesidePanel(render::FrameData& frame, const ViewDesc& view);

// "0.0123 rad, dE/E +1.2e-05, since 3.2 s" (the time the spin was last torqued), or the one
// reason the body is not compared: static, kinematic, asleep, or torqued this step.
std::string freeFlightRow(const FreeFlightError& error, const World& world);

// The overlay's row "restitution below" when a body has restitution > 0: "0.5 m/s approach:
// none" (Settings::restitutionThreshold: slower approaches do not bounce), or that it is off.
// Empty when nothing bounces.
std::string restitutionThresholdRow(const World& world);

// "+1.0000 -2.0000 +0.5000 m": the overlay's format of a vector.
std::string formatVec(const Vec3& v, const char* unit);
// "0.25 J": the overlay's format of a number.
std::string formatNumber(double value, const char* unit);

}  // namespace rbsim::app
