// Joints in the soft step (soft_step_solver.h): a ball joint's point constraint and a hinge's
// two angular rows, motor and limits, in 3D after Box2D v3's src/revolute_joint.c (warm start,
// then per sweep motor, limits, point) and src/solver.c (joint softness, soft with bias and
// rigid in the relax). Each joint is solved as one block: the point's 3 x 3 effective mass and
// the axis's 2 x 2 are inverted exactly, so a single joint is satisfied in one sweep. Springs,
// friction, the ball's cone and twist, the prismatic and weld joints are in joints/*.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "dynamics/contact_key.h"
#include "dynamics/soft_step_solver.h"

namespace rbsim {

namespace {

// The stiffness and damping ratio of the joints' soft constraints in the biased solve, capped
// like the contacts at a quarter of the substep rate (Box2D v3's solver.c). Box2D v3.0's
// b2DefaultWorldDef has 60 Hz and 2; stiffer and less damped, a pendulum keeps more of its
// energy (tests/engine/dynamics/joint_test.cpp, 1e4 swings at dt = 1/60 s: 60 Hz, 2: 75 % of the
// swing energy lost; 120 Hz, 0.5: 16 %; 120 Hz, 0: 8 %) and a chain of ten links holds its
// joints within 1 mm (2 mm at 60 Hz). 0.5 keeps some damping against ringing in long chains.
constexpr double kJointHertz = 120.0;                // [Hz]
constexpr double kJointDampingRatio = 0.5;           // [1]
constexpr double kMaxJointHertzPerSubstepRate = 0.25;  // [1]

// Whether a joint needs more than a plain ball's or hinge's rows (SoftStepSolver::jointExtras_).
bool needsExtra(const JointDef& def) {
  return def.spring || def.friction > 0.0 || def.coneLimit || (def.type == JointDef::Type::Ball && def.limits) ||
         def.type == JointDef::Type::Prismatic || def.type == JointDef::Type::Weld;
}

// A joint's bodies' indices now: A's, and B's or kOnWorld for the world.
constexpr std::size_t kOnWorld = SIZE_MAX;
std::size_t indexA(const IdTable<BodyId>& bodyIds, const Joint& joint) { return bodyIds.indexOf(joint.def.bodyA); }
std::size_t indexB(const IdTable<BodyId>& bodyIds, const Joint& joint) {
  return joint.def.bodyB == kWorldAnchor ? kOnWorld : bodyIds.indexOf(joint.def.bodyB);
}

Mat3 skew(const Vec3& r) {
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

}  // namespace

void SoftStepSolver::slotJoints(const std::vector<RigidBody>& bodies, const IdTable<BodyId>& bodyIds,
                                std::vector<Joint>& joints, const Settings& settings, bool addGravity) {
  for (const Joint& joint : joints) {
    const std::size_t a = indexA(bodyIds, joint), b = indexB(bodyIds, joint);
    const bool awake = bodies[a].awake() || (b != kOnWorld && bodies[b].awake());
    if (!awake) continue;
    slot(bodies, a, settings, addGravity);
    if (b != kOnWorld) slot(bodies, b, settings, addGravity);
  }
}

void SoftStepSolver::prepareJoints(const std::vector<RigidBody>& bodies, const IdTable<BodyId>& bodyIds,
                                   std::vector<Joint>& joints, const Settings& settings) {
  const double h = settings.timeStep / settings.substeps;
  jointSoftness_ = makeSoftness(std::min(kJointHertz, kMaxJointHertzPerSubstepRate / h), kJointDampingRatio, h);
  jointExtras_.clear();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    Joint& joint = joints[i];
    const std::size_t a = indexA(bodyIds, joint), b = indexB(bodyIds, joint);
    JointConstraint c;
    c.joint = i;
    c.data = &joint;
    c.type = joint.def.type;
    c.moving = slotOfBody_[a];
    c.base = b == kOnWorld ? 0 : slotOfBody_[b];
    // Body A is dynamic (scene/joint_parser.cpp, World::addJoint), and the World wakes both
    // sides of a joint together: without a slot, A is asleep with its base.
    if (c.moving == 0) continue;
    if (sims_[c.moving].inverseMass == 0.0) continue;  // kinematic on both sides: nothing to solve
    c.localAnchorMoving = joint.localAnchorMoving;
    c.localAxisMoving = joint.localAxisMoving;
    // A base without a slot (the world, or a static body) never moves: its anchor and axis are
    // taken into world frame once, which is the ground slot's frame.
    c.localAnchorBase = joint.localAnchorBase;
    c.localAxisBase = joint.localAxisBase;
    c.baseOrientation = Quat::Identity();
    if (c.base == 0 && b != kOnWorld) {
      c.localAnchorBase = bodies[b].position() + bodies[b].rotation() * joint.localAnchorBase;
      c.localAxisBase = bodies[b].rotation() * joint.localAxisBase;
      c.baseOrientation = bodies[b].orientation();
    }
    const JointDef& def = joint.def;
    if (!settings.warmStarting) {
      joint.linearImpulse.setZero();
      joint.angularImpulse.setZero();
      joint.motorImpulse = joint.lowerImpulse = joint.upperImpulse = joint.swingImpulse = 0.0;
      joint.springImpulse.setZero();
      joint.frictionImpulse.setZero();
    }
    if (!def.motor) joint.motorImpulse = 0.0;
    if (!def.limits) joint.lowerImpulse = joint.upperImpulse = 0.0;
    // A joint without extras never writes their impulses: they stay zero.
    if (needsExtra(def)) {
      if (!def.coneLimit) joint.swingImpulse = 0.0;
      if (!def.spring) joint.springImpulse.setZero();
      if (!(def.friction > 0.0)) joint.frictionImpulse.setZero();
      joint_rows::Extra extra;
      if (def.spring) extra.spring = makeSoftness(def.springHertz, def.springDampingRatio, h);
      if (def.linearHertz > 0.0) extra.weldLinear = makeSoftness(def.linearHertz, def.linearDampingRatio, h);
      if (def.angularHertz > 0.0) extra.weldAngular = makeSoftness(def.angularHertz, def.angularDampingRatio, h);
      if (def.type == JointDef::Type::Ball && (def.limits || def.coneLimit)) {
        const Quat base = b == kOnWorld ? Quat::Identity() : bodies[b].orientation();
        const Vec3 coneAxis = base * joint.localAxisBase, twistAxis = bodies[a].orientation() * joint.localAxisMoving;
        joint_rows::prepareBallLimits(coneAxis, twistAxis, extra);
      }
      c.extra = static_cast<int>(jointExtras_.size());
      jointExtras_.push_back(extra);
    }
    joints_.push_back(c);
  }
}

void SoftStepSolver::warmStartJoints(std::size_t island) {
  islands_.forJoints(island, [&](std::size_t index) {
    const JointConstraint& c = joints_[index];
    const Joint& joint = *c.data;
    SolverState& A = states_[c.base];
    SolverState& B = states_[c.moving];
    const Vec3 rA = A.orientation * c.localAnchorBase;
    const Vec3 rB = B.orientation * c.localAnchorMoving;
    Vec3 linear = joint.linearImpulse, angular = joint.angularImpulse;
    Vec3 armA = rA;  // where A feels the linear impulse, from its centre
    // A plain ball joint has its point's impulse only.
    if (c.type != JointDef::Type::Ball || c.extra >= 0) {
      const Vec3 axis = A.orientation * c.localAxisBase;
      const double axial = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
      switch (c.type) {
        case JointDef::Type::Hinge:
          angular += axial * axis;
          if (c.extra >= 0) angular += joint.springImpulse + joint.frictionImpulse;
          break;
        case JointDef::Type::Ball: {
          const joint_rows::Extra& extra = jointExtras_[static_cast<std::size_t>(c.extra)];
          angular += joint.springImpulse + joint.frictionImpulse + (joint.lowerImpulse - joint.upperImpulse) * extra.twistJacobian -
                     joint.swingImpulse * extra.swingAxis;
          break;
        }
        case JointDef::Type::Prismatic: {
          // Box2D v3's prismatic_joint.c: A's lever arm reaches B's anchor, d + rA.
          linear += axial * axis + joint.springImpulse + joint.frictionImpulse;
          const Vec3 xA = sims_[c.base].position0 + A.deltaPosition, xB = sims_[c.moving].position0 + B.deltaPosition;
          armA = (xB + rB) - xA;
          break;
        }
        case JointDef::Type::Weld:
          break;
      }
    }
    if (c.base != 0) {
      A.linearVelocity -= sims_[c.base].inverseMass * linear;
      A.angularVelocity -= sims_[c.base].inverseInertiaNow * (armA.cross(linear) + angular);
    }
    if (c.moving != 0) {
      B.linearVelocity += sims_[c.moving].inverseMass * linear;
      B.angularVelocity += sims_[c.moving].inverseInertiaNow * (rB.cross(linear) + angular);
    }
  });
}

void SoftStepSolver::solveJoints(std::size_t island, double h, bool useBias) {
  const double inverseH = 1.0 / h;
  islands_.forJoints(island, [&](std::size_t index) {
    const JointConstraint& c = joints_[index];
    Joint& joint = *c.data;
    const JointDef& def = joint.def;
    SolverState& A = states_[c.base];
    SolverState& B = states_[c.moving];
    const double mA = sims_[c.base].inverseMass, mB = sims_[c.moving].inverseMass;
    const Mat3& iA = sims_[c.base].inverseInertiaNow;
    const Mat3& iB = sims_[c.moving].inverseInertiaNow;
    Vec3 vA = A.linearVelocity, wA = A.angularVelocity, vB = B.linearVelocity, wB = B.angularVelocity;
    // The ground slot's orientation is the identity and its position zero, so its "local"
    // anchor and axis are world ones.
    const Vec3 xA = sims_[c.base].position0 + A.deltaPosition, xB = sims_[c.moving].position0 + B.deltaPosition;
    const Vec3 rA = A.orientation * c.localAnchorBase, rB = B.orientation * c.localAnchorMoving;
    const Softness soft = useBias ? jointSoftness_ : Softness{};

    if (c.extra >= 0) {
      const joint_rows::Extra& extra = jointExtras_[static_cast<std::size_t>(c.extra)];
      const joint_rows::Frame f{xA, xB, rA, rB, (A.orientation * c.localAxisBase).normalized(),
                                c.base == 0 ? c.baseOrientation : A.orientation, B.orientation};
      joint_rows::Pair p{vA, wA, vB, wB, mA, mB, &iA, &iB};
      switch (c.type) {
        case JointDef::Type::Hinge:
          joint_rows::solveHingeExtras(joint, extra, f, h, p);
          break;
        case JointDef::Type::Ball:
          joint_rows::solveBallAngular(joint, extra, f, h, soft, useBias, p);
          break;
        case JointDef::Type::Prismatic:
          joint_rows::solvePrismatic(joint, extra, f, h, soft, useBias, p);
          storeVelocities(c.base, p.vA, p.wA);
          storeVelocities(c.moving, p.vB, p.wB);
          return;
        case JointDef::Type::Weld:
          joint_rows::solveWeld(joint, extra, f, soft, p);
          storeVelocities(c.base, p.vA, p.wA);
          storeVelocities(c.moving, p.vB, p.wB);
          return;
      }
      vA = p.vA;
      wA = p.wA;
      vB = p.vB;
      wB = p.wB;
    }

    if (c.type == JointDef::Type::Hinge) {
      const Vec3 axis = (A.orientation * c.localAxisBase).normalized();
      const double axialInverse = axis.dot((iA + iB) * axis);
      const double axialMass = axialInverse > 0.0 ? 1.0 / axialInverse : 0.0;
      const auto applyAxial = [&](double impulse) {
        wA -= impulse * (iA * axis);
        wB += impulse * (iB * axis);
      };
      // The angle now, for the motor (which must not drive past a limit) and the limits.
      const double angle = (def.motor || def.limits) ? hingeAngle(joint, c.base == 0 ? c.baseOrientation : A.orientation, B.orientation) : 0.0;
      if (def.motor && axialMass > 0.0) {  // revolute_joint.c: Cdot = wB - wA - speed, |lambda| <= h tau_max
        // At or past a stop it drives into, the motor lets go and the stop alone acts: a stop holds
        // against any motor. Box2D lets a motor stronger than the soft limit's spring push through
        // (a door driven at 1e6 N m ran 1 rad past its stop); a motor held at zero speed there would
        // in turn keep the door from springing back to the stop.
        const bool intoStop = def.limits && ((angle <= def.lowerAngle && def.motorSpeed < 0.0) ||
                                             (angle >= def.upperAngle && def.motorSpeed > 0.0));
        const double cdot = axis.dot(wB - wA) - def.motorSpeed;
        const double old = joint.motorImpulse;
        const double maxImpulse = h * def.maxMotorTorque;
        joint.motorImpulse = intoStop ? 0.0 : std::clamp(old - axialMass * cdot, -maxImpulse, maxImpulse);
        applyAxial(joint.motorImpulse - old);
      }
      if (def.limits && axialMass > 0.0) {
        // Lower: C = angle - lower >= 0; upper: C = upper - angle >= 0, signs flipped so that
        // both impulses are >= 0. A limit not reached is speculative (the gap may close within
        // the substep, no further); a reached one is soft with bias, rigid in the relax.
        for (int side = 0; side < 2; ++side) {
          const double sign = side == 0 ? 1.0 : -1.0;
          const double C = side == 0 ? angle - def.lowerAngle : def.upperAngle - angle;
          double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
          if (C > 0.0) {
            bias = C * inverseH;
          } else if (useBias) {
            bias = soft.biasRate * C;
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
          }
          double& accumulated = side == 0 ? joint.lowerImpulse : joint.upperImpulse;
          const double cdot = sign * axis.dot(wB - wA);
          const double old = accumulated;
          accumulated = std::max(old - massScale * axialMass * (cdot + bias) - impulseScale * old, 0.0);
          applyAxial(sign * (accumulated - old));
        }
      }
    }

    if (c.type == JointDef::Type::Ball) {
      // The point's three rows alone, written out (the block below, for R = 3, with its zero
      // blocks left out): K = (mA + mB) 1 + [rA] iA [rA]^T + [rB] iB [rB]^T,
      // Cdot = (vB + wB x rB) - (vA + wA x rA); the impulse acts +lambda at B's anchor and
      // -lambda at A's. A third of the block's work on Box3D's 19701-joint grid. K is symmetric
      // positive definite (mA + mB > 0: one body moves), so it is inverted in closed form, by
      // cofactors, as Box2D's b2Solve33 does by Cramer's rule, not factored with pivoting.
      const Mat3 sA = skew(rA), sB = skew(rB);
      const Mat3 K = (mA + mB) * Mat3::Identity() + sA * iA * sA.transpose() + sB * iB * sB.transpose();
      const Vec3 cdot = (vB + wB.cross(rB)) - (vA + wA.cross(rA));
      const Vec3 error = (xB + rB) - (xA + rA);
      const Vec3 lambda = -soft.massScale * (K.inverse() * (cdot + soft.biasRate * error)) - soft.impulseScale * joint.linearImpulse;
      joint.linearImpulse += lambda;
      storeVelocities(c.base, vA - mA * lambda, wA - iA * rA.cross(lambda));
      storeVelocities(c.moving, vB + mB * lambda, wB + iB * rB.cross(lambda));
      return;
    }

    // A hinge: the point (rows 0-2) and the axes held aligned (rows 3-4), as one block:
    //   C = [(xB + rB) - (xA + rA);  t_k . (a_base x a_moving)],  Cdot = J_A u_A + J_B u_B,
    //   J_A = [-1  [rA]; 0  -T],  J_B = [1  -[rB]; 0  T],  K = J M^-1 J^T
    // for T the two unit t_k perpendicular to the base's axis, as rows (seed 000's K of a contact
    // point, extended by the angular rows), solved exactly, so one joint alone needs one sweep.
    // K's blocks written out, as the ball's above (the dense 5 x 6 products spent two thirds of
    // their work on zeros):
    //   K = [(mA + mB) 1 + [rA] iA [rA]^T + [rB] iB [rB]^T,  -([rA] iA + [rB] iB) T^T;
    //        sym.,                                            T (iA + iB) T^T].
    Vec3 tangents[2];
    const Vec3 axis = (A.orientation * c.localAxisBase).normalized();
    tangentBasis(axis, tangents[0], tangents[1]);
    Eigen::Matrix<double, 2, 3> T;
    T.row(0) = tangents[0].transpose();
    T.row(1) = tangents[1].transpose();
    const Mat3 sA = skew(rA), sB = skew(rB);
    const Mat3 sAiA = sA * iA, sBiB = sB * iB;
    Eigen::Matrix<double, 5, 5> K;
    K.topLeftCorner<3, 3>() = (mA + mB) * Mat3::Identity() + sAiA * sA.transpose() + sBiB * sB.transpose();
    K.topRightCorner<3, 2>() = -(sAiA + sBiB) * T.transpose();
    K.bottomLeftCorner<2, 3>() = K.topRightCorner<3, 2>().transpose();
    K.bottomRightCorner<2, 2>() = T * (iA + iB) * T.transpose();
    Eigen::Matrix<double, 5, 1> cdot, error, accumulated;
    cdot.head<3>() = (vB + wB.cross(rB)) - (vA + wA.cross(rA));
    cdot.tail<2>() = T * (wB - wA);
    error.head<3>() = (xB + rB) - (xA + rA);
    error.tail<2>() = T * axis.cross((B.orientation * c.localAxisMoving).normalized());
    accumulated.head<3>() = joint.linearImpulse;
    accumulated.tail<2>() = T * joint.angularImpulse;
    const Eigen::Matrix<double, 5, 1> impulse =
        -soft.massScale * K.ldlt().solve(cdot + soft.biasRate * error) - soft.impulseScale * accumulated;
    // u += M^-1 J^T lambda: the point's impulse +lambda at B's anchor and -lambda at A's, the
    // angular rows' T^T lambda as a torque on B and its opposite on A.
    const Vec3 linear = impulse.head<3>();
    const Vec3 angular = T.transpose() * impulse.tail<2>();
    vA -= mA * linear;
    wA -= iA * (rA.cross(linear) + angular);
    vB += mB * linear;
    wB += iB * (rB.cross(linear) + angular);
    joint.linearImpulse += linear;
    const Eigen::Vector2d total = accumulated.tail<2>() + impulse.tail<2>();
    joint.angularImpulse = T.transpose() * total;

    storeVelocities(c.base, vA, wA);
    storeVelocities(c.moving, vB, wB);
  });
}

}  // namespace rbsim
