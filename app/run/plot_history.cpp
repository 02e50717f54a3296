#include "run/plot_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rbsim/collision/contact.h"
#include "rbsim/math/rotation.h"

namespace rbsim::app {

namespace {

// The window of a scene without an end (the window mode's): the last this many seconds [s].
constexpr double kScrollingSeconds = 10.0;

double potentialEnergy(const World& world, const RigidBody& body) {
  return -body.mass() * world.settings().gravity.dot(body.position());
}

std::size_t contactsOf(const World& world, bool selectedOnly, std::size_t selected) {
  if (!selectedOnly) return world.contactPoints().size();
  std::size_t count = 0;
  for (const SolvedContactPoint& p : world.contactPoints()) {
    const Contact& c = world.contacts()[p.contact];
    if (c.b == selected || (c.kind == Contact::Kind::BodyBody && c.a == selected)) ++count;
  }
  return count;
}

}  // namespace

double plotQuantity(const std::string& name, const World& world, bool selectedOnly, std::size_t selected,
                    const FreeFlightError* freeFlight) {
  const std::vector<RigidBody>& bodies = world.bodies();
  const bool one = selectedOnly && selected < bodies.size();
  if (selectedOnly && !one) return std::numeric_limits<double>::quiet_NaN();
  const auto sum = [&](auto of) {
    if (one) return of(bodies[selected]);
    double total = 0.0;
    for (const RigidBody& b : bodies) total += of(b);
    return total;
  };
  if (name == "ke") return sum([](const RigidBody& b) { return b.kineticEnergy(); });
  if (name == "pe") return sum([&](const RigidBody& b) { return potentialEnergy(world, b); });
  if (name == "E") return sum([&](const RigidBody& b) { return b.kineticEnergy() + potentialEnergy(world, b); });
  if (name == "|P|") {
    if (one) return bodies[selected].state().linearMomentum.norm();
    Vec3 P = Vec3::Zero();
    for (const RigidBody& b : bodies) P += b.state().linearMomentum;
    return P.norm();
  }
  if (name == "|L|") {
    if (one) return bodies[selected].state().angularMomentum.norm();
    Vec3 L = Vec3::Zero();
    for (const RigidBody& b : bodies) L += b.position().cross(b.state().linearMomentum) + b.state().angularMomentum;
    return L.norm();
  }
  if (name == "contacts") return static_cast<double>(contactsOf(world, selectedOnly, selected));
  if (name == "drift") {
    // How far R is from a rotation, ||R^T R - I||_F: zero but for rounding unless euler-matrix runs
    // without drift correction (seed 004 "Drift correction"); the scene's largest.
    if (one) return orthonormalityError(bodies[selected].rotation());
    double largest = 0.0;
    for (const RigidBody& b : bodies) largest = std::max(largest, orthonormalityError(b.rotation()));
    return largest;
  }
  if (name == "error") {
    if (freeFlight == nullptr) return std::numeric_limits<double>::quiet_NaN();
    const FreeFlightError::Reading reading = freeFlight->read(world);
    return reading.tracked ? reading.angle : std::numeric_limits<double>::quiet_NaN();
  }
  return std::numeric_limits<double>::quiet_NaN();  // the scene loader admits only kPlotQuantities
}

std::pair<std::string, std::string> plotUnitAndTitle(const std::string& name, bool selectedOnly) {
  if (name == "ke") return {"J", "kinetic energy"};
  if (name == "pe") return {"J", "potential energy -m g.x"};
  if (name == "E") return {"J", "E = kinetic + potential"};
  if (name == "|P|") return {"kg m/s", "|P|, linear momentum"};
  if (name == "|L|") return {"kg m^2/s", selectedOnly ? "|L| about the centre of mass" : "|L| about the origin"};
  if (name == "contacts") return {"", "contact points"};
  if (name == "error") return {"rad", "angle from the exact spin"};
  if (name == "drift") return {"", "||R^T R - I||, R's drift from a rotation"};
  return {"", name};
}

TimePlots::TimePlots(const Phase& phase) {
  const ViewDesc& view = phase.scene().view;
  names_ = view.plots;
  selectedOnly_ = view.plotSelected;
  // The time axis spans the whole scene unless view.plot_seconds asks for a window that scrolls.
  double duration = 0.0;
  for (const PhaseWorld& w : phase.worlds) {
    duration = std::max(duration, static_cast<double>(w.scene.stepCount()) * w.scene.settings.timeStep);
  }
  seconds_ = view.plotSeconds > 0.0 ? view.plotSeconds : std::isfinite(duration) && duration > 0.0 ? duration : kScrollingSeconds;
  for (const PhaseWorld& w : phase.worlds) {
    selected_.push_back(w.scene.view.selected);
    // "world.integrator = dlm" is "dlm" in a legend whose plot the panel names.
    const std::string prefix = phase.compareKey + " = ";
    const bool keyed = w.label.rfind(prefix, 0) == 0;
    legend_.push_back(!phase.compared() ? "" : keyed ? w.label.substr(prefix.size()) : w.label);
  }
  const std::vector<BodyDef>& bodies = phase.scene().bodies;
  if (selected_.front() < bodies.size()) bodyName_ = bodies[selected_.front()].name;
  series_.assign(names_.size(), std::vector<Series>(phase.worlds.size()));
}

void TimePlots::sample(const std::vector<World>& worlds, const std::vector<FreeFlightError>* freeFlight) {
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    sample(worlds[k], freeFlight != nullptr && k < freeFlight->size() ? &(*freeFlight)[k] : nullptr, k);
  }
}

void TimePlots::sample(const World& world, const FreeFlightError* freeFlight, std::size_t k) {
  now_ = std::max(now_, world.time());
  for (std::size_t p = 0; p < names_.size(); ++p) {
    Series& s = series_[p][k];
    s.t.push_back(static_cast<float>(world.time()));
    s.y.push_back(static_cast<float>(plotQuantity(names_[p], world, selectedOnly_, selected_[k], freeFlight)));
    while (!keepHistory_ && !s.t.empty() && s.t.front() < now_ - seconds_) {
      s.t.pop_front();
      s.y.pop_front();
    }
  }
}

std::vector<render::OverlayPlot> TimePlots::plotsAt(double t) const {
  std::vector<render::OverlayPlot> out;
  // The window stands still while it fills, then scrolls with the time.
  const float tMax = static_cast<float>(std::max(t, seconds_));
  const float tMin = tMax - static_cast<float>(seconds_);
  const float until = static_cast<float>(t);
  for (std::size_t p = 0; p < names_.size(); ++p) {
    render::OverlayPlot plot;
    const auto [unit, title] = plotUnitAndTitle(names_[p], selectedOnly_);
    plot.unit = unit;
    plot.title = selectedOnly_ && !bodyName_.empty() ? bodyName_ + ": " + title : title;
    plot.legend = legend_;
    plot.tMax = tMax;
    plot.tMin = tMin;
    plot.nonNegative = names_[p] != "pe" && names_[p] != "E";  // the rest are lengths, counts, kinetic energy
    for (const Series& s : series_[p]) {
      // The samples in [t - seconds, t] (all of them, unless history is kept).
      const auto first = std::lower_bound(s.t.begin(), s.t.end(), static_cast<float>(t - seconds_));
      const auto last = std::upper_bound(first, s.t.end(), until);
      const auto from = first - s.t.begin(), to = last - s.t.begin();
      plot.times.emplace_back(first, last);
      plot.values.emplace_back(s.y.begin() + from, s.y.begin() + to);
    }
    out.push_back(std::move(plot));
  }
  return out;
}

}  // namespace rbsim::app
