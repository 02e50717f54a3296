#include "accuracy/measure.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "rbsim/math/rotation.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/world.h"

namespace rbsim::accuracy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A step count is duration / dt rounded; 1e-9 keeps 0.05 / (1/60) = 3 from flooring to 2.
constexpr double kRoundingSlack = 1e-9;  // [1]

World makeWorld(const ReferenceCase& c, Integrator integrator, double dt) {
  Settings settings;
  settings.gravity = c.gravity;
  settings.timeStep = dt;
  settings.integrator = integrator;
  settings.allowSleep = false;  // the sweep measures integration, never a body put to rest
  World world(settings);
  const BodyId body = world.addBody(c.body);
  for (ScriptedForce f : c.forces) {  // the case's forces name no body until it is in a World
    f.body = body;
    world.addForce(f);
  }
  return world;
}

// Total energy [J]: kinetic plus the potential -m g.x of uniform gravity (zero at the origin).
double totalEnergy(const RigidBody& body, const Vec3& gravity) {
  return body.kineticEnergy() - body.mass() * gravity.dot(body.position());
}

double relativeDrift(double value, double initial) {
  return initial != 0.0 ? std::abs(value / initial - 1.0) : std::abs(value);
}

// A flip counts only when the intermediate axis turns over relative to the (fixed) angular
// momentum: the direction cosine L_body[axis] / |L| swings from beyond +kFlipCosine to beyond
// -kFlipCosine or back (a Schmitt trigger). For a body whose body axes are its principal axes,
// L_body[axis] = I[axis] omega_body[axis], so its zero crossings are those of omega_body[axis].
// Plain sign changes would also count the wobble of a body that gained energy and spins about
// its long axis (the forward-Euler family): there the component oscillates about zero with a
// decaying amplitude, hundreds of sign changes and no flip.
constexpr double kFlipCosine = 0.5;  // [1]: the axis within 60 degrees of +L or of -L
// A body that has not flipped for this many half periods (the exact one or its own mean, the
// longer) before the end of the run has stopped flipping: it has settled into another spin.
constexpr double kStoppedHalfPeriods = 2.0;  // [1]

// Times of the flips, each the zero crossing (interpolated linearly between the two steps that
// bracket it) last before the direction cosine passed the threshold on the other side.
class FlipTracker {
 public:
  FlipTracker(int axis, const RigidBody& body) : axis_(axis), previous_(cosine(body)) { side_ = sideOf(previous_); }

  void update(const RigidBody& body, double tPrevious, double dt) {
    const double value = cosine(body);
    if ((previous_ < 0.0) != (value < 0.0)) lastZero_ = tPrevious + dt * previous_ / (previous_ - value);
    const int side = sideOf(value);
    if (side != 0 && side != side_) {
      if (side_ != 0) flips_.push_back(lastZero_);  // from one side to the other: a flip
      side_ = side;
    }
    previous_ = value;
  }

  int count() const { return static_cast<int>(flips_.size()); }
  double lastFlip() const { return flips_.empty() ? kNaN : flips_.back(); }
  // Mean interval between successive flips [s]: (last - first) / (count - 1). The first flip is
  // not measured from t = 0, which is an arbitrary phase of the motion.
  double meanHalfPeriod() const {
    if (flips_.size() < 2) return kNaN;
    return (flips_.back() - flips_.front()) / static_cast<double>(flips_.size() - 1);
  }

 private:
  double cosine(const RigidBody& body) const {
    const Vec3& L = body.state().angularMomentum;  // world frame
    return (body.rotation().transpose() * L)[axis_] / L.norm();
  }
  int sideOf(double value) const { return value >= kFlipCosine ? 1 : (value <= -kFlipCosine ? -1 : 0); }

  int axis_;
  double previous_;        // the direction cosine after the previous step [1]
  int side_ = 0;           // +1 or -1: the side last beyond the threshold; 0 before any
  double lastZero_ = 0.0;  // [s]
  std::vector<double> flips_;
};

}  // namespace

const char* flipStatusName(FlipStatus status) {
  switch (status) {
    case FlipStatus::NotApplicable: return "n/a";
    case FlipStatus::Flipping: return "flipping";
    case FlipStatus::WrongCount: return "wrong-count";
    case FlipStatus::NoFlip: return "no-flip";
  }
  return "unknown";
}

Accuracy measureAccuracy(const ReferenceCase& c, Integrator integrator, double dt, double duration,
                         double sampleInterval, double earlyHorizon) {
  World world = makeWorld(c, integrator, dt);
  const RigidBody& body = world.bodies().front();
  const double energy0 = totalEnergy(body, c.gravity);
  const double momentum0 = body.state().angularMomentum.norm();
  const long steps = std::lround(duration / dt);
  const long stride = std::max(1L, static_cast<long>(std::floor(sampleInterval / dt + kRoundingSlack)));
  FlipTracker flips(c.flipAxis, body);

  Accuracy a;
  for (long i = 1; i <= steps; ++i) {
    const double tPrevious = world.time();
    try {
      world.step();
    } catch (const SimulationError& e) {
      a.diverged = true;
      a.divergence = e.what();
      break;
    }
    a.energyDriftFinal = relativeDrift(totalEnergy(body, c.gravity), energy0);
    a.momentumDriftFinal = relativeDrift(body.state().angularMomentum.norm(), momentum0);
    a.energyDriftMax = std::max(a.energyDriftMax, a.energyDriftFinal);
    a.momentumDriftMax = std::max(a.momentumDriftMax, a.momentumDriftFinal);
    if (c.flips) flips.update(body, tPrevious, dt);
    // The exact rotation costs a quadrature, so it is sampled rather than evaluated every step.
    if (i % stride == 0 || i == steps) {
      const double t = world.time();
      a.orientErrFinal = rotationAngleBetween(c.exactRotation(t), body.rotation());
      a.positionErrFinal = (body.position() - c.exactPosition(t)).norm();
      a.orientErrMax = std::max(a.orientErrMax, a.orientErrFinal);
      if (t <= earlyHorizon + kRoundingSlack * dt) a.orientErrMaxEarly = a.orientErrMax;
      a.positionErrMax = std::max(a.positionErrMax, a.positionErrFinal);
    }
  }
  if (a.diverged) {
    // The state at the end does not exist; the maxima cover the run up to the divergence.
    a.orientErrFinal = a.energyDriftFinal = a.momentumDriftFinal = a.positionErrFinal = kNaN;
  }

  if (c.flips) {
    a.flipCount = flips.count();
    a.lastFlip = flips.lastFlip();
    a.flipHalfPeriod = flips.meanHalfPeriod();
    const double patience = kStoppedHalfPeriods * std::max(c.exactHalfPeriod, a.flipHalfPeriod);
    const bool stopped = !(world.time() - a.lastFlip <= patience);  // also true with no flip at all
    if (a.flipCount < 2 || stopped) {
      // A period measured from flips that then ceased describes no motion the body ends in.
      a.flipStatus = FlipStatus::NoFlip;
      a.flipHalfPeriod = a.flipPeriodErr = kNaN;
    } else {
      a.flipStatus = a.flipCount == c.exactFlipCount ? FlipStatus::Flipping : FlipStatus::WrongCount;
      a.flipPeriodErr = std::abs(a.flipHalfPeriod - c.exactHalfPeriod) / c.exactHalfPeriod;
    }
  } else {
    a.lastFlip = a.flipHalfPeriod = a.flipPeriodErr = kNaN;
  }
  return a;
}

Timing measureTiming(const ReferenceCase& c, Integrator integrator, double dt, double duration,
                     double minTotalSeconds, int minRepeats) {
  using Clock = std::chrono::steady_clock;
  Timing timing;
  timing.steps = std::lround(duration / dt);
  std::vector<double> runs;
  double total = 0.0;
  volatile double sink = 0.0;  // the final state is read, so the runs cannot be optimised away
  while (total < minTotalSeconds || static_cast<int>(runs.size()) < minRepeats) {
    World world = makeWorld(c, integrator, dt);
    const auto start = Clock::now();
    try {
      for (long i = 0; i < timing.steps; ++i) world.step();
    } catch (const SimulationError&) {
      // A run that stops early has no cost per 20 s to report.
      timing.repeats = static_cast<int>(runs.size());
      timing.medianRunSeconds = timing.minRunSeconds = kNaN;
      return timing;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    sink = sink + world.bodies().front().position().x() + world.bodies().front().orientation().w();
    runs.push_back(seconds);
    total += seconds;
  }
  std::sort(runs.begin(), runs.end());
  timing.repeats = static_cast<int>(runs.size());
  const std::size_t mid = runs.size() / 2;
  timing.medianRunSeconds = runs.size() % 2 == 1 ? runs[mid] : 0.5 * (runs[mid - 1] + runs[mid]);
  timing.minRunSeconds = runs.front();
  return timing;
}

}  // namespace rbsim::accuracy
