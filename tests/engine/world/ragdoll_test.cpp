// The ragdoll preset (engine/src/world/ragdoll.cpp): dropped onto a plane, tumbling, it comes to
// rest with every joint within its limits, to the soft limits' give.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rbsim/world/joint_reading.h"
#include "rbsim/world/ragdoll.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

TEST(Ragdoll, DroppedOnAPlaneComesToRestWithEveryJointWithinItsLimits) {
  for (double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    Settings s;
    s.timeStep = dt;
    s.gravity = Vec3(0.0, -9.81, 0.0);
    s.allowSleep = false;
    World world(s);
    world.addPlane(Plane{Vec3::UnitY(), 0.0});
    RagdollDef def;
    def.position = Vec3(0.0, 0.5, 0.0);
    def.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3(1.0, 0.0, 1.0).normalized()));  // tipped: it falls over
    def.velocity = Vec3(1.0, 0.0, 0.5);
    const Ragdoll ragdoll = addRagdoll(world, def);
    ASSERT_EQ(world.bodies().size(), kBoneCount);
    ASSERT_EQ(world.joints().size(), kBoneCount - 1);
    // Past a limit by more than the soft limit's give under a limb's weight at a fall's speed.
    constexpr double kSlack = 0.05;  // [rad]
    double worstExcess = 0.0, worstDrift = 0.0;
    const int steps = static_cast<int>(std::lround(6.0 / dt));
    for (int i = 0; i < steps; ++i) {
      world.step();
      if (i < steps / 2) continue;  // the second half: fallen and settling
      for (std::size_t j : ragdoll.joints) {
        const Joint& joint = world.joints()[j];
        const JointReading r = readJoint(world, j);
        double excess = 0.0;
        if (joint.def.type == JointDef::Type::Ball) {
          excess = std::max({r.swing - joint.def.coneAngle, r.twist - joint.def.upperAngle, joint.def.lowerAngle - r.twist});
        } else {
          excess = std::max(r.angle - joint.def.upperAngle, joint.def.lowerAngle - r.angle);
        }
        worstExcess = std::max(worstExcess, excess);
        worstDrift = std::max(worstDrift, (r.anchorA - r.anchorB).norm());
      }
    }
    double fastest = 0.0, lowest = 1e9;
    for (const RigidBody& b : world.bodies()) {
      fastest = std::max(fastest, b.velocity().norm());
      lowest = std::min(lowest, b.position().y());
    }
    const double pelvis = world.bodies()[static_cast<std::size_t>(Bone::Pelvis)].position().y();
    std::printf("ragdoll, dt %.5f s: worst excess past a limit %.4f rad, widest joint gap %.4f m, fastest bone at 6 s %.4f m/s, "
                "pelvis at %.3f m\n", dt, worstExcess, worstDrift, fastest, pelvis);
    EXPECT_LT(pelvis, 0.3) << "dt " << dt;  // it fell over (it stood with its pelvis at 1.48 m)
    EXPECT_LT(worstExcess, kSlack) << "dt " << dt;
    EXPECT_LT(worstDrift, 0.01) << "dt " << dt;  // a joint holds its bones within a centimetre
    EXPECT_LT(fastest, 0.05) << "dt " << dt;     // at rest
    EXPECT_GT(lowest, 0.0);                      // on the plane, not through it
  }
}

}  // namespace
}  // namespace rbsim
