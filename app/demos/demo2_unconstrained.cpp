// Demo 2: assignment 2, rigid body unconstrained motion (seed 004). Seven phases, one video:
// (a) x and R set by hand, the engine's vertex list drawn as dots over the box; (b) given v and
// omega; (c) a force at an off-centre point, with the
// torque it produces; (d) a general mesh with exact inertia beside its cube approximation, its
// energy plotted; (e) that mesh under three integrators side by side, energy and error plotted;
// (f) a hinged door pushed at its handle (torque about the hinge) and a pendulum on a ball joint;
// (g) seed 004's matrix update R += dt omega* R with and without its drift correction.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo2Unconstrained() {
  return Demo{2, "assignment2", "rigid body unconstrained motion: manual pose, v and omega, "
                                "force at a point, exact vs cube inertia, integrators side by side, "
                                "a hinged door and a compound pendulum, R += dt omega* R with and without drift correction",
              {"assignment2_a_manual_pose.json", "assignment2_b_velocity.json",
               "assignment2_c_force_at_point.json", "assignment2_d_mesh_inertia.json",
               "assignment2_e_integrators.json", "assignment2_f_joints.json", "assignment2_g_matrix_drift.json"}};
}

}  // namespace rbsim::app
