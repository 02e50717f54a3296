#pragma once
// `rbsim replay FILE --window` (issue 24): a recording in an X11 window with a timeline to scrub
// back and forth, play and pause, and step frame by frame; the orbit camera of window mode. Any
// frame is drawn again by restoring its kept state (window/replay_timeline.h), without simulating.
#include <string>
#include <vector>

#include "record/recording.h"
#include "run/phase.h"
#include "window/interactive.h"

namespace rbsim::app {

// Runs until the window is closed or options.frames have been shown. Throws InputError when the
// recording is damaged or too large to keep, WindowError without a display.
void runReplayWindow(const std::vector<Phase>& phases, RecordReader& reader, const std::string& recording,
                     const WindowOptions& options);

}  // namespace rbsim::app
