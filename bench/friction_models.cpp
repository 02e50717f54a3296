// Issue 25: the two friction models (Settings::FrictionModel, world.friction) and the
// restitution law measured against their analytic values, for REPORT section 5. Each row: a
// solver, a friction model and a time step; the cases are bench/friction_cases.h's.
//   usage: friction_models            (about 10 s)
#include <cstdio>

#include "friction_cases.h"

using namespace rbsim;
using namespace rbsim::bench;

int main() {
  const double v0 = 2.0;  // [m/s]
  const double distance = v0 * v0 / (2.0 * kCaseKineticFriction * kFrictionG);
  const double steep = 40.0 * M_PI / 180.0;  // above the friction angle of 30.96 degrees
  const double slideAcceleration = kFrictionG * (std::sin(steep) - kCaseKineticFriction * std::cos(steep));
  std::printf("mu_s %.2f, mu_k %.2f; slide from %.1f m/s: %.4f m expected; 40 deg incline: %.4f m/s^2 expected\n",
              kCaseStaticFriction, kCaseKineticFriction, v0, distance, slideAcceleration);
  std::printf("%-9s %-8s %-6s %12s %12s %14s %14s %12s\n", "solver", "friction", "dt", "slide [m]", "slide err",
              "creep 25deg mm", "creep 30deg mm", "accel 40deg");
  for (const auto solver : {Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs}) {
    for (const auto friction : {Settings::FrictionModel::Cone, Settings::FrictionModel::Seed000}) {
      for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
        const Settings s = frictionCaseSettings(solver, friction, dt);
        const SlideResult slide = slideToStop(s, v0);
        const InclineResult shallow = incline(s, 25.0, 10.0), steepest = incline(s, 30.0, 10.0);
        const InclineResult sliding = incline(s, 40.0, 1.0);
        std::printf("%-9s %-8s 1/%-4.0f %12.4f %+11.2f%% %14.3f %14.3f %12.4f\n",
                    solver == Settings::ContactSolverMethod::Pgs ? "pgs" : "soft-step", frictionModelName(friction),
                    1.0 / dt, slide.distance, 100.0 * (slide.distance / distance - 1.0), 1e3 * shallow.slide,
                    1e3 * steepest.slide, sliding.acceleration);
      }
    }
  }
  std::printf("\nrestitution_threshold 0: leave speed / (c_R sqrt(2 g h)) - 1 [%%], box and ball\n");
  std::printf("%-9s %-6s %6s %8s %10s %10s\n", "solver", "dt", "c_R", "h [m]", "box", "ball");
  for (const auto solver : {Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs}) {
    for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
      const Settings s = restitutionSettings(solver, dt);
      for (const double e : {0.3, 0.7, 1.0}) {
        for (const double h : {0.01, 1.0}) {
          const BounceResult box = dropAndBounce(s, e, h, false), ball = dropAndBounce(s, e, h, true);
          std::printf("%-9s 1/%-4.0f %6.1f %8.2f %+9.2f%% %+9.2f%%\n",
                      solver == Settings::ContactSolverMethod::Pgs ? "pgs" : "soft-step", 1.0 / dt, e, h,
                      100.0 * (box.leaveSpeed / (e * box.impactSpeed) - 1.0),
                      100.0 * (ball.leaveSpeed / (e * ball.impactSpeed) - 1.0));
        }
      }
    }
  }
  return 0;
}
