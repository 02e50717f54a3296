#pragma once
// One (case, integrator, dt) cell of the accuracy sweep: an accuracy run that compares the World
// with the exact motion, and a separate timing run that never evaluates the reference.
#include <string>

#include "accuracy/cases.h"
#include "rbsim/integrate/integrator.h"

namespace rbsim::accuracy {

// Whether the flip half period could be measured (case 1 only).
enum class FlipStatus {
  NotApplicable,  // the case does not flip
  Flipping,       // as many flips as the exact motion
  WrongCount,     // at least two flips, but fewer or more than the exact motion
  NoFlip,         // under two flips, or none for the last two half periods (the body settled
                  // into another spin): the half period and its error are NaN
};
const char* flipStatusName(FlipStatus status);

struct Accuracy {
  bool diverged = false;           // World::step threw SimulationError; the maxima stop there
  std::string divergence;          // its message
  double orientErrMax = 0.0;       // max over samples of angle(R_exact^T R) [rad]
  double orientErrFinal = 0.0;     // the same at the end of the run [rad]
  double orientErrMaxEarly = 0.0;  // max over the samples up to earlyHorizon [rad]
  double energyDriftMax = 0.0;     // max |E / E0 - 1|, E kinetic + potential (-m g.x) [1]
  double energyDriftFinal = 0.0;   // [1]
  double momentumDriftMax = 0.0;   // max | |L| / |L0| - 1 |, L about the centre of mass [1]
  double momentumDriftFinal = 0.0; // [1]
  double positionErrMax = 0.0;     // max |x - x_exact| [m]
  double positionErrFinal = 0.0;   // [m]
  FlipStatus flipStatus = FlipStatus::NotApplicable;
  int flipCount = 0;               // reversals of omega_body[flipAxis] (measure.cpp, FlipTracker)
  double lastFlip = 0.0;           // time of the last one [s]; NaN if none
  double flipHalfPeriod = 0.0;     // mean time between successive flips [s]; NaN if NoFlip
  double flipPeriodErr = 0.0;      // |flipHalfPeriod - T/2| / (T/2) [1]; NaN if NoFlip
};

// Runs the case for `duration` [s] at step dt [s], sampling the exact orientation and position at
// least every sampleInterval [s] (and at the end); energy, |L| and flips are checked every step.
// orientErrMaxEarly covers only [0, earlyHorizon] [s].
Accuracy measureAccuracy(const ReferenceCase& c, Integrator integrator, double dt, double duration,
                         double sampleInterval, double earlyHorizon);

struct Timing {
  int repeats = 0;             // whole runs timed
  double medianRunSeconds = 0.0;  // median wall time of one run of `duration` [s]; NaN if diverged
  double minRunSeconds = 0.0;     // the fastest run [s]; NaN if diverged
  long steps = 0;              // steps per run
};

// Times whole runs (World construction excluded) until at least minTotalSeconds [s] of wall time
// and minRepeats runs have accumulated; steady_clock, no reference evaluation inside the loop.
Timing measureTiming(const ReferenceCase& c, Integrator integrator, double dt, double duration,
                     double minTotalSeconds, int minRepeats);

}  // namespace rbsim::accuracy
