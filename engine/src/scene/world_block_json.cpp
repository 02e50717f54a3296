// A scene's "world" block written back: every key parseWorldBlock reads, with the value it would
// read (tests/engine/scene/world_block_json_test.cpp reads it back for defaults and for a scene
// that changes every key). Python's World.settings and World()'s signature come from here, so the
// keys and defaults a user sees are the parser's own.
#include "rbsim/scene/scene_parts.h"

#include "rbsim/integrate/integrator.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/particles/particle_def.h"

namespace rbsim {

nlohmann::json worldBlockJson(const Scene& scene) {
  const Settings& s = scene.settings;
  nlohmann::json w = nlohmann::json::object();
  w["gravity"] = {s.gravity.x(), s.gravity.y(), s.gravity.z()};
  w["dt"] = s.timeStep;
  w["integrator"] = integratorName(s.integrator);
  w["drift_correction"] = s.driftCorrection;
  w["inertia"] = inertiaMethodName(s.inertia);
  w["duration"] = scene.duration;
  w["sleep"] = s.allowSleep;
  w["sleep_linear_speed"] = s.sleepLinearSpeed;
  w["sleep_angular_speed"] = s.sleepAngularSpeed;
  w["time_to_sleep"] = s.timeToSleep;
  w["collisions"] = s.detectCollisions;
  w["ccd"] = s.continuousCollision;
  w["ccd_motion_fraction"] = s.ccdMotionFraction;
  w["broad_phase"] = broadPhaseName(s.broadPhase);
  w["contact_margin"] = s.contactMargin;
  if (s.contactRecycleDistance == kAutoRecycleDistance) {
    w["contact_recycle_distance"] = "auto";
  } else {
    w["contact_recycle_distance"] = s.contactRecycleDistance;
  }
  w["solver"] = contactSolverName(s.solver);
  w["friction"] = frictionModelName(s.friction);
  w["mesh_contact"] = meshContactName(s.meshContact);
  w["substeps"] = s.substeps;
  w["contact_hertz"] = s.contactHertz;
  w["contact_damping_ratio"] = s.contactDampingRatio;
  w["contact_push_speed"] = s.contactPushSpeed;
  w["velocity_iterations"] = s.velocityIterations;
  w["position_iterations"] = s.positionIterations;
  w["restitution_threshold"] = s.restitutionThreshold;
  w["hit_event_speed"] = s.hitEventSpeed;
  w["contact_slop"] = s.contactSlop;
  w["position_correction"] = s.positionCorrection;
  w["warm_starting"] = s.warmStarting;
  w["warm_start_distance"] = s.warmStartDistance;
  w["response"] = s.respondToContacts;
  w["log_queries"] = s.logQueries;
  w["query_log_capacity"] = s.queryLogCapacity;
  w["skip_idle_stages"] = s.skipIdleStages;
  w["threads"] = s.threads;
  w["particle_integrator"] = particleIntegratorName(scene.particleIntegrator);
  return w;
}

}  // namespace rbsim
