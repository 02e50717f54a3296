// A weld (fixed) joint: A's anchor held at the base's and A's orientation at the one it was
// added in, after Box2D v3's src/weld_joint.c: the three angular rows, then the point's three,
// each block with its own softness. A weld of 0 Hz has the joints' softness in the biased sweep
// and is rigid in the relax, as every joint; given hertz, it is that spring in both sweeps.
#include <Eigen/Dense>

#include "dynamics/joints/joint_rows.h"

namespace rbsim::joint_rows {

void solveWeld(Joint& joint, const Extra& extra, const Frame& f, const Softness& soft, Pair& p) {
  const JointDef& def = joint.def;
  const Softness angular = def.angularHertz > 0.0 ? extra.weldAngular : soft;
  solveAngularSpring(rotationMass(p), relativeRotation(joint, f.base, f.moving), angular, joint.angularImpulse, p);

  // The point: K = (mA + mB) 1 - [rA] iA [rA] - [rB] iB [rB], as the ball joint's.
  const Softness linear = def.linearHertz > 0.0 ? extra.weldLinear : soft;
  const auto skew = [](const Vec3& r) {
    Mat3 m;
    m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
    return m;
  };
  const Mat3 sA = skew(f.rA), sB = skew(f.rB);
  const Mat3 K = (p.mA + p.mB) * Mat3::Identity() + sA * *p.iA * sA.transpose() + sB * *p.iB * sB.transpose();
  const Vec3 cdot = (p.vB + p.wB.cross(f.rB)) - (p.vA + p.wA.cross(f.rA));
  const Vec3 error = (f.xB + f.rB) - (f.xA + f.rA);
  const Vec3 lambda =
      -linear.massScale * K.ldlt().solve(cdot + linear.biasRate * error) - linear.impulseScale * joint.linearImpulse;
  joint.linearImpulse += lambda;
  p.vA -= p.mA * lambda;
  p.wA -= *p.iA * f.rA.cross(lambda);
  p.vB += p.mB * lambda;
  p.wB += *p.iB * f.rB.cross(lambda);
}

}  // namespace rbsim::joint_rows
