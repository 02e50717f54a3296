#pragma once
// The three reference cases of the accuracy sweep (issue 3): each is a single body with an initial
// state, the gravity it needs and its exact motion from bench/reference, so any integrator run
// through rbsim::World can be compared with the truth at any time.
#include <functional>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/math/types.h"
#include "rbsim/world/scripts.h"

namespace rbsim::accuracy {

struct ReferenceCase {
  std::string name;         // key in the CSV, e.g. "torque-free-box"
  std::string description;  // one line for the summary
  BodyDef body;             // initial state; BodyDef takes omega in world frame
  Vec3 gravity = Vec3::Zero();  // [m/s^2]
  std::vector<ScriptedForce> forces;  // held on for the whole run (the torqued case)
  bool conservative = true;     // whether E is conserved (no work done by the forces)

  // Exact motion: body-to-world rotation and centre-of-mass position at time t [s].
  std::function<Mat3(double)> exactRotation;
  std::function<Vec3(double)> exactPosition;

  // Dzhanibekov flips (case 1 only): the body-frame omega component about flipAxis reverses
  // every exactHalfPeriod, exactFlipCount times within the sweep's duration.
  bool flips = false;
  int flipAxis = 1;              // body axis (0 = x, 1 = y, 2 = z), the intermediate one
  double exactHalfPeriod = 0.0;  // [s]
  int exactFlipCount = 0;        // sign changes of the exact omega component in the duration
};

// The torque-free asymmetric box near its intermediate axis, the symmetric top, the spinning
// projectile, and the box under a torque fixed in the body (its reference: world-frame RK4 at
// 1/30000 s, error ~1e-10 rad over 20 s), with exact flip counts for a run of `duration` [s].
std::vector<ReferenceCase> referenceCases(double duration);

// The box's omega period quoted in issue 3 [s] (reference::TorqueFreeExact::period() gives it to
// ~1e-12 s; the sweep checks the two agree before trusting its flip-period errors).
inline constexpr double kBoxOmegaPeriod = 8.895484030056;

}  // namespace rbsim::accuracy
