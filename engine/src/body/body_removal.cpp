#include "body/body_removal.h"

#include <algorithm>
#include <numeric>

namespace rbsim {

BodyRemoval::BodyRemoval(std::size_t before, std::vector<Step> steps) : before_(before), steps_(std::move(steps)) {
  // Per index now, the index before the batch of the body there: only indices a removal reached
  // ever differ from their own.
  std::vector<std::uint32_t> origin(before_);
  std::iota(origin.begin(), origin.end(), std::uint32_t{0});
  struct Raw {
    std::uint32_t body;
    Event event;
  };
  std::vector<Raw> raw;
  raw.reserve(2 * steps_.size());
  for (std::uint32_t t = 0; t < steps_.size(); ++t) {
    const Step& s = steps_[t];
    raw.push_back({origin[s.removed], {t, kGone}});
    removed_.push_back(origin[s.removed]);
    if (s.removed == s.last) continue;
    raw.push_back({origin[s.last], {t, s.removed}});
    origin[s.removed] = origin[s.last];
  }
  // Events by body, each body's in step order (raw is in step order; the fill is stable).
  eventStart_.assign(before_ + 1, 0);
  for (const Raw& r : raw) ++eventStart_[r.body + 1];
  std::partial_sum(eventStart_.begin(), eventStart_.end(), eventStart_.begin());
  events_.resize(raw.size());
  std::vector<std::uint32_t> next(eventStart_.begin(), eventStart_.end() - 1);
  newIndex_.resize(before_);
  std::iota(newIndex_.begin(), newIndex_.end(), std::uint32_t{0});
  for (const Raw& r : raw) {
    events_[next[r.body]++] = r.event;
    newIndex_[r.body] = r.event.to;  // a body's last event is where it ends, or kGone
  }
  std::vector<std::uint32_t> reached;
  for (const Step& s : steps_) {
    if (s.removed < after()) reached.push_back(s.removed);
  }
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  for (const std::uint32_t i : reached) {
    if (origin[i] != i) moves_.emplace_back(i, origin[i]);
  }
}

}  // namespace rbsim
