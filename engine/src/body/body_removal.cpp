#include "body/body_removal.h"

#include <algorithm>
#include <unordered_map>

namespace rbsim {

BodyRemoval::BodyRemoval(std::size_t before, std::vector<Step> steps) : before_(before), steps_(std::move(steps)) {
  // Per index now, the index before the batch of the body there, for the indices a removal
  // reached (every other index holds its own body): O(k) for k steps, whatever the World's size.
  std::unordered_map<std::uint32_t, std::uint32_t> origin;
  origin.reserve(2 * steps_.size());
  const auto originOf = [&origin](std::uint32_t index) {
    const auto at = origin.find(index);
    return at == origin.end() ? index : at->second;
  };
  struct Raw {
    std::uint32_t body;
    std::uint32_t to;  // where the body went at that step, or kGone
  };
  std::vector<Raw> raw;
  raw.reserve(2 * steps_.size());
  for (std::uint32_t t = 0; t < steps_.size(); ++t) {
    const Step& s = steps_[t];
    const std::uint32_t removedBody = originOf(s.removed);
    raw.push_back({removedBody, kGone});
    removed_.push_back(removedBody);
    if (s.removed == s.last) continue;
    const std::uint32_t lastBody = originOf(s.last);
    raw.push_back({lastBody, s.removed});
    origin[s.removed] = lastBody;
  }
  // By body, each body's in step order (raw is in step order; the sort is stable): a body's last
  // is where it ends, or kGone.
  std::stable_sort(raw.begin(), raw.end(), [](const Raw& x, const Raw& y) { return x.body < y.body; });
  for (const Raw& r : raw) {
    if (involved_.empty() || involved_.back().body != r.body) involved_.push_back({r.body, r.body});
    involved_.back().newIndex = r.to;
  }
  std::vector<std::uint32_t> reached;
  for (const Step& s : steps_) {
    if (s.removed < after()) reached.push_back(s.removed);
  }
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  for (const std::uint32_t i : reached) {
    const std::uint32_t from = originOf(i);
    if (from != i) moves_.emplace_back(i, from);
  }
}

const BodyRemoval::Involved* BodyRemoval::find(std::size_t index) const {
  const auto at = std::lower_bound(involved_.begin(), involved_.end(), index,
                                   [](const Involved& x, std::size_t i) { return x.body < i; });
  return at != involved_.end() && at->body == index ? &*at : nullptr;
}

}  // namespace rbsim
