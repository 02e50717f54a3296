#pragma once
// A phase's worlds in one frame (app/run/phase.h): each world's frame built as for a scene alone
// (frame_builder.h), moved by the world's offset, and merged; a caption naming each world's
// value is pinned below it. The overlay shows the selected body of every world, row under row.
#include <string>
#include <vector>

#include "render/frame_data.h"
#include "run/phase.h"
#include "rbsim/world/free_flight_error.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// `worlds[k]` was built from phase.worlds[k].scene; `freeFlight[k]`, when given, follows its
// selected body (the "vs exact spin" rows).
render::FrameData buildPhaseFrame(const std::vector<World>& worlds, const Phase& phase, const std::string& demoTitle,
                                  const std::vector<FreeFlightError>* freeFlight = nullptr);

}  // namespace rbsim::app
