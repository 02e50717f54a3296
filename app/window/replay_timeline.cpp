#include "window/replay_timeline.h"

#include <algorithm>

#include "rbsim/io/input_error.h"
#include "run/runner.h"

namespace rbsim::app {

ReplayTimeline::ReplayTimeline(const std::vector<Phase>& phases, RecordReader& reader, const std::string& recording)
    : phases_(phases), reader_(reader) {
  std::size_t bytes = 0;
  for (std::size_t p = 0; p < phases_.size(); ++p) {
    const Phase& phase = phases_[p];
    std::vector<World> worlds;
    for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
    std::vector<FreeFlightError> freeFlight;  // for the error plot, as the run had it
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      freeFlight.emplace_back(selectedBodyId(worlds[k], phase.worlds[k].scene.view.selected));
      freeFlight.back().observe(worlds[k]);
    }
    std::vector<KeptEntry> latest(worlds.size());
    plots_.push_back(std::make_unique<TimePlots>(phase));
    plots_.back()->keepHistory();
    const double fps = phase.scene().view.fps;
    const std::uint64_t frames = frameCount(phase);
    for (std::uint64_t f = 0; f < frames; ++f) {
      KeptFrame kept;
      kept.phase = p;
      for (std::size_t k = 0; k < worlds.size(); ++k) {
        const Scene& scene = phase.worlds[k].scene;
        const std::uint64_t target = std::min(stepOfFrame(f, fps, scene.settings.timeStep), scene.stepCount());
        while (worlds[k].stepCount() < target) {
          reader_.restoreNext(k, worlds.size(), worlds[k]);
          freeFlight[k].observe(worlds[k]);
          latest[k] = reader_.lastEntry();
        }
        // A snapshot of changed bodies counts once, at the first frame that keeps it.
        const bool newBodySet = latest[k].bodySet && (frames_.empty() || frames_.back().phase != p ||
                                                       frames_.back().entries[k].bodySet != latest[k].bodySet);
        bytes += latest[k].state.size() + (newBodySet ? latest[k].bodySet->size() : 0);
        if (bytes > kMaxTimelineBytes) {
          throw InputError(recording, "--window",
                           "the window keeps every frame's state to scrub, and this recording needs more than " +
                               std::to_string(kMaxTimelineBytes >> 20) + " MiB of it by frame " +
                               std::to_string(frames_.size() + 1) + "; replay it into a video instead (without --window)");
        }
        kept.entries.push_back(latest[k]);
      }
      kept.time = worlds.front().time();
      kept.freeFlight = freeFlight;
      if (!plots_.back()->empty()) plots_.back()->sample(worlds, &freeFlight);
      frames_.push_back(std::move(kept));
    }
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      while (worlds[k].stepCount() < phase.worlds[k].scene.stepCount()) reader_.restoreNext(k, worlds.size(), worlds[k]);
    }
  }
  reader_.expectEnd();
  if (frames_.empty()) throw InputError(recording, "--window", "the recording has no frame to show");
  show(0);
}

void ReplayTimeline::show(std::size_t frame) {
  const KeptFrame& kept = frames_.at(frame);
  const Phase& phase = phases_[kept.phase];
  if (!built_ || shownPhase_ != kept.phase) {
    worlds_.clear();
    shownBodySets_.clear();
    for (const PhaseWorld& w : phase.worlds) worlds_.push_back(buildWorld(w.scene));
    shownPhase_ = kept.phase;
    built_ = true;
  }
  shownBodySets_.resize(worlds_.size());
  for (std::size_t k = 0; k < worlds_.size(); ++k) {
    const KeptEntry& entry = kept.entries[k];
    // The bodies the frame shows: the scene's own, or those of the snapshot of their last change.
    const bool sameBodies = entry.bodySet == shownBodySets_[k];
    if (entry.empty() || (!sameBodies && !entry.bodySet)) {
      worlds_[k] = buildWorld(phase.worlds[k].scene);  // step 0: the scene's own start
    }
    shownBodySets_[k] = entry.bodySet;
    if (entry.empty()) continue;
    if (sameBodies && entry.bodySet) {
      KeptEntry state;  // the World holds these bodies already: the states alone
      state.state = entry.state;
      reader_.restore(state, k, worlds_[k]);
    } else {
      reader_.restore(entry, k, worlds_[k]);
    }
  }
  current_ = frame;
}

std::vector<render::OverlayPlot> ReplayTimeline::plots() const {
  const TimePlots& plots = *plots_[frames_[current_].phase];
  return plots.empty() ? std::vector<render::OverlayPlot>{} : plots.plotsAt(time());
}

}  // namespace rbsim::app
