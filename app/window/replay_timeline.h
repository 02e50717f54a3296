#pragma once
// Every frame of a recording at hand, to draw any of them again in any order (the replay window's
// timeline, issue 24): the recording is read once, stepping each phase's worlds through it as
// `rbsim replay` does (runner.h's frames), and each frame keeps its worlds' entries
// (recording.h) and the plots' samples; showing a frame restores its entries into the worlds.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "record/recording.h"
#include "run/phase.h"
#include "run/plot_history.h"
#include "rbsim/world/free_flight_error.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// The most recorded state a timeline keeps in memory [bytes]; a recording that needs more is
// refused (replay it into a video instead, or record fewer bodies or frames).
inline constexpr std::size_t kMaxTimelineBytes = std::size_t{2} << 30;

class ReplayTimeline {
 public:
  // Reads all of `reader` (InputError naming `recording` when it is damaged, does not belong to
  // `phases`, or needs more than kMaxTimelineBytes), then shows frame 0.
  ReplayTimeline(const std::vector<Phase>& phases, RecordReader& reader, const std::string& recording);

  std::size_t frames() const { return frames_.size(); }
  std::size_t current() const { return current_; }
  void show(std::size_t frame);  // frame < frames()

  // What the current frame shows: its phase, its worlds at their steps, its plots.
  const Phase& phase() const { return phases_[frames_[current_].phase]; }
  std::size_t phaseIndex() const { return frames_[current_].phase; }
  const std::vector<World>& worlds() const { return worlds_; }
  double time() const { return frames_[current_].time; }  // of the phase's first world [s]
  std::vector<render::OverlayPlot> plots() const;
  // Each world's selected body against the exact spin, as the run followed it to this frame.
  const std::vector<FreeFlightError>& freeFlight() const { return frames_[current_].freeFlight; }

 private:
  struct KeptFrame {
    std::size_t phase = 0;
    double time = 0.0;
    std::vector<KeptEntry> entries;  // per world; empty at step 0 (the scene's start)
    std::vector<FreeFlightError> freeFlight;         // per world, as the run had it at this frame
  };

  const std::vector<Phase>& phases_;
  RecordReader& reader_;
  std::vector<KeptFrame> frames_;
  std::vector<std::unique_ptr<TimePlots>> plots_;  // per phase, every sample kept
  std::vector<World> worlds_;
  std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> shownBodySets_;  // per world: whose bodies it holds
  std::size_t shownPhase_ = 0, current_ = 0;
  bool built_ = false;
};

}  // namespace rbsim::app
