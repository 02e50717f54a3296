#include "rbsim/settings/settings.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "rbsim/math/format_number.h"

namespace rbsim {

int machineThreads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(std::min<unsigned>(cores, kMaxThreads));
}

namespace {

// A finite value within [lo, hi]; NaN fails every comparison, so it is refused too.
bool within(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

}  // namespace

SettingsProblem checkSettings(const Settings& s) {
  const double inf = INFINITY;
  if (!(s.timeStep > 0.0)) return {"dt", "expected a positive time step, got " + formatNumber(s.timeStep) + " s"};
  if (!within(s.timeStep, kMinTimeStep, kMaxTimeStep)) {
    return {"dt", "expected a time step in [" + formatNumber(kMinTimeStep) + ", " + formatNumber(kMaxTimeStep) + "] s; " +
                      formatNumber(s.timeStep) + " s is absurd"};
  }
  if (!s.gravity.allFinite() || !(s.gravity.stableNorm() <= kMaxGravity)) {
    return {"gravity", "expected finite components, |g| at most " + formatNumber(kMaxGravity) +
                           " m/s^2 (above a neutron star's surface gravity)"};
  }
  if (!s.driftCorrection && s.integrator != Integrator::EulerMatrix) {
    return {"drift_correction", std::string("expected true with integrator \"") + integratorName(s.integrator) +
                                    "\": false keeps euler-matrix's raw R, and only that integrator has one"};
  }
  if (!within(s.sleepLinearSpeed, 0.0, inf)) return {"sleep_linear_speed", "expected a finite speed >= 0 m/s"};
  if (!within(s.sleepAngularSpeed, 0.0, inf)) return {"sleep_angular_speed", "expected a finite speed >= 0 rad/s"};
  if (!within(s.timeToSleep, 0.0, inf) || s.timeToSleep == 0.0) return {"time_to_sleep", "expected a finite time > 0 s"};
  if (!within(s.contactMargin, 0.0, kMaxContactTolerance)) {
    return {"contact_margin", "expected a distance in [0, 1] m (a tolerance: past a metre every nearby pair is in contact)"};
  }
  if (!within(s.ccdMotionFraction, 0.0, inf) || s.ccdMotionFraction == 0.0) {
    return {"ccd_motion_fraction", "expected a finite fraction > 0 of a body's thinnest extent"};
  }
  if (s.queryLogCapacity < 1 || s.queryLogCapacity > kMaxQueryLogCapacity) {
    return {"query_log_capacity", "expected 1 to " + std::to_string(kMaxQueryLogCapacity) + " records"};
  }
  if (s.threads < 1 || s.threads > kMaxThreads) {
    return {"threads", "expected a whole number of threads in [1, " + std::to_string(kMaxThreads) + "]"};
  }
  if (s.substeps < 1 || s.substeps > kMaxSubsteps) {
    return {"substeps", "expected a positive integer in [1, " + std::to_string(kMaxSubsteps) + "] substeps"};
  }
  if (!within(s.contactHertz, 0.0, inf)) return {"contact_hertz", "expected a finite frequency >= 0 Hz"};
  if (!within(s.contactDampingRatio, 0.0, inf)) return {"contact_damping_ratio", "expected a finite damping ratio >= 0"};
  if (!within(s.contactPushSpeed, 0.0, inf) || s.contactPushSpeed == 0.0) {
    return {"contact_push_speed", "expected a positive finite speed [m/s]"};
  }
  const std::string sweeps = "at most " + std::to_string(kMaxSolverIterations) +
                             " sweeps a step (Box2D v2 uses 8, Bullet 10); each sweep visits every contact point";
  if (s.velocityIterations < 1 || s.velocityIterations > kMaxSolverIterations) {
    return {"velocity_iterations", "expected at least 1 and " + sweeps};
  }
  // The lcp solver's friction is the cone at each manifold's centroid (dynamics/lcp_solver.h).
  if (s.solver == Settings::ContactSolverMethod::Lcp && s.friction == Settings::FrictionModel::Seed000) {
    return {"friction", "the lcp solver has the cone's friction only; expected \"cone\" with world.solver \"lcp\""};
  }
  if (s.positionIterations < 0 || s.positionIterations > kMaxSolverIterations) {
    return {"position_iterations", "expected 0 or more and " + sweeps};
  }
  if (!within(s.restitutionThreshold, 0.0, inf)) return {"restitution_threshold", "expected a finite speed >= 0 m/s"};
  if (!within(s.hitEventSpeed, 0.0, inf)) return {"hit_event_speed", "expected a finite speed >= 0 m/s"};
  if (!within(s.contactSlop, 0.0, kMaxContactTolerance)) {
    return {"contact_slop", "expected a distance in [0, 1] m (a tolerance, not a reach)"};
  }
  if (!within(s.positionCorrection, 0.0, 1.0)) return {"position_correction", "expected a fraction in [0, 1]"};
  if (!within(s.warmStartDistance, 0.0, inf)) return {"warm_start_distance", "expected a finite distance >= 0 m"};
  if (s.contactRecycleDistance != kAutoRecycleDistance && !within(s.contactRecycleDistance, 0.0, kMaxContactTolerance)) {
    return {"contact_recycle_distance", "expected \"auto\" or a distance in [0, 1] m (0: collide every pair every step)"};
  }
  return {};
}

double recycleDistance(const Settings& s) {
  if (s.solver != Settings::ContactSolverMethod::SoftStep) return 0.0;
  if (s.contactRecycleDistance != kAutoRecycleDistance) return s.contactRecycleDistance;
  const double h = s.timeStep / s.substeps;
  return kRecycleGravityFactor * s.gravity.norm() * h * h;
}

const char* contactSolverName(Settings::ContactSolverMethod method) {
  switch (method) {
    case Settings::ContactSolverMethod::Pgs: return "pgs";
    case Settings::ContactSolverMethod::Lcp: return "lcp";
    case Settings::ContactSolverMethod::SoftStep: break;
  }
  return "soft-step";
}

const char* broadPhaseName(Settings::BroadPhaseMethod method) {
  return method == Settings::BroadPhaseMethod::BruteForce ? "brute-force" : "sap";
}

const char* meshContactName(Settings::MeshContact method) {
  return method == Settings::MeshContact::Triangles ? "triangles" : "samples";
}

const char* frictionModelName(Settings::FrictionModel model) {
  return model == Settings::FrictionModel::Seed000 ? "seed000" : "cone";
}

bool parseFrictionModel(const std::string& name, Settings::FrictionModel& model) {
  if (name == "cone") {
    model = Settings::FrictionModel::Cone;
  } else if (name == "seed000") {
    model = Settings::FrictionModel::Seed000;
  } else {
    return false;
  }
  return true;
}

}  // namespace rbsim
