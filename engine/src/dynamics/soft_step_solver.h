#pragma once
// Stage SolveContacts with Settings::solver = soft-step (the default): the "soft step" of Catto,
// "Solver2D" (2024), as Box2D v3 runs it (src/solver.c b2SolverStage, src/contact_solver.c).
// Every awake body that touches something is advanced by this solver over the whole step, in
// Settings::substeps substeps of
//   integrate velocities (forces, gravity), warm start, solve (soft contacts, with bias),
//   integrate positions, relax (solve again, rigid and without bias);
// then one restitution pass and the impulses kept for the next step's warm start. Bodies without
// contact are left to the World's integrator, so free flight is exactly what it always was.
//
// Contact anchors stay fixed in the bodies across the substeps and each point's separation is
// updated from them (s = s0 + n . (dx_B + dR_B r_B - dx_A - dR_A r_A), Box2D v3's comment at the
// top of contact_solver.c): collision detection runs once per step, not per substep.
//
// A penetrating point is a soft constraint: a spring of Settings::contactHertz and
// contactDampingRatio solved implicitly over the substep (Catto, "Soft Constraints", GDC 2011),
// which gives the bias velocity, a mass scale and an impulse scale (softness.h). The relax sweep
// then removes the velocity that bias added, so pushing out never becomes kinetic energy.
//
// Joints (dynamics/joint.h) are solved with the contacts, before them in every sweep (Box2D v3's
// b2SolverStage order): soft in the biased solve, rigid in the relax (soft_step_joints.cpp). Every
// awake jointed body is advanced by this solver, touching something or not.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "dynamics/contact_key.h"
#include "dynamics/contact_solver.h"
#include "dynamics/joints/joint_rows.h"
#include "math/key_index.h"
#include "rbsim/dynamics/softness.h"
#include "rbsim/dynamics/solver_islands.h"
#include "rbsim/math/parallel.h"

namespace rbsim {

class SoftStepSolver final : public ContactSolver {
 public:
  Order order() const override { return Order::CollideFirst; }
  bool solvesJoints() const override { return true; }
  // Advances by settings.timeStep every awake body in a contact with a manifold (x, q, P, L),
  // using the forces and torques accumulated in it, plus m g when `addGravity`, and every awake
  // body of a joint, whose warm-start impulses are read and written back. Clears their
  // accumulators.
  void solve(const SolverInput& input) override;
  void forget() override {
    clearAdvanced();
    cache_.clear();
    cacheIndex_.clear();
    asleepCache_.clear();
    solved_.clear();
    hits_.clear();
    reported_ = true;
  }
  void bodiesRemoved(const std::vector<std::uint32_t>& removed, const std::vector<std::uint64_t>& goneAsleep) override;
  // soft_step_finish.cpp
  void contactsSlept(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys) override;
  void contactsWoke(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys) override;
  void contactsReindexed(const std::vector<std::uint32_t>& newIndex) override;
  void clearAdvanced() override {
    for (std::size_t body : advancedList_) advanced_[body] = 0;
    advancedList_.clear();
  }
  const std::vector<std::size_t>& advancedBodies() const override { return advancedList_; }
  const std::vector<char>& advancedFlags() const override { return advanced_; }  // per World body
  void save(ByteWriter& out) const override;  // dynamics/solver_snapshot.cpp
  void load(ByteReader& in, const std::vector<std::uint32_t>& bodyKeys, bool keyedByIndex) override;
  std::unique_ptr<ContactSolver> clone() const override { return std::make_unique<SoftStepSolver>(*this); }
  // Built when first asked for after a step (most steps nobody asks: 60,000 points of Box3D's
  // pyramid took 5 % of its step), from what the step left in the constraints and states.
  const std::vector<SolvedContactPoint>& points() const override {
    if (!reported_) report();
    return solved_;
  }
  // Kept by finish(), which reads each point's report anyway, at Settings::hitEventSpeed.
  void hits(double speed, std::vector<ContactHit>& out) const override {
    for (const ContactHit& hit : hits_) {
      if (hit.approachSpeed > speed) out.push_back(hit);
    }
  }

 private:
  // Hot: what a substep reads and writes per body, 112 bytes with q aligned to 16 (Box2D's
  // b2BodyState). Slot 0 is the ground (planes and static bodies): it never moves and is never
  // written.
  struct SolverState {
    Vec3 linearVelocity = Vec3::Zero();   // v [m/s]
    Vec3 angularVelocity = Vec3::Zero();  // omega [rad/s]
    Vec3 deltaPosition = Vec3::Zero();    // x - x0 [m]
    Quat orientation = Quat::Identity();  // q now
  };
  static_assert(!kStatedLayout || sizeof(SolverState) == 112, "the size the comment above states");
  // Per body and step, read once per substep at most.
  struct BodySim {
    std::size_t body = 0;                    // World index
    double inverseMass = 0.0;                // [1/kg]
    Mat3 inverseInertiaNow = Mat3::Zero();   // R I_body^-1 R^T for the current orientation
    Vec3 position0 = Vec3::Zero();           // x at the step's start [m]
    Vec3 acceleration = Vec3::Zero();        // F / m (+ g) over the step [m/s^2]
    Vec3 torque = Vec3::Zero();              // tau about x [N m]
    bool kinematic = false;                  // moves as prescribed, infinite mass (zero inverses)
  };
  // 168 bytes, 2.6 cache lines: the index and 1/m (16), I^-1 now (72), x0, a and tau (72), the
  // flag. Read at a substep's velocity and position integration, not by the sweeps.
  static_assert(sizeof(BodySim) == 168, "BodySim's size: see the comment above");
  // One manifold point, in three arrays indexed alike, so that each pass streams only what it
  // reads (Box2D v3 keeps its solver points apart from the manifold the same way): the sweeps of
  // every substep read and write Point; the relax, once a substep, reads PointFrame too; the
  // step's start and end (prepare, restitution, the report) use PointReport.
  // A Point holds the lever arms and effective masses of the step's start only (Box2D v3 and
  // Box3D prepare them once a step, contact_solver.c); the sweeps form r x n and I^-1 (r x n)
  // from them as they go: computing is cheaper than streaming those six vectors from memory (the
  // point was 304 bytes and the sweeps of Box3D's large pyramid waited on memory).
  struct Point {  // 112 bytes
    // From each centre of mass now to the point both bodies push at, world [m]: one point for
    // both, so that every impulse changes x x P + L of the pair by (p - p) x j = 0 and angular
    // momentum is exchanged exactly (fixed arms, as Box2D keeps them, would lose
    // (dx_B - dx_A) x j). The relax moves it with the bodies once a substep (updateArms).
    Vec3 anchorA = Vec3::Zero(), anchorB = Vec3::Zero();
    double separation = 0.0;         // s at the current poses [m]
    double normalMass = 0.0;         // 1 / (n^T K n) at the step's start [kg]
    std::array<double, 2> tangentMass{};  // 1 / (t_k^T K t_k) [kg]
    double tangentCoupling = 0.0;    // t1^T K t2, for seed 000's K_TT (friction_law.h) [1/kg]
    double normalImpulse = 0.0;      // this substep's (warm start: the last one's) [N s]
    std::array<double, 2> tangentImpulse{};  // along t1, t2 [N s]
  };
  static_assert(sizeof(Point) == 112, "the size the comment above states");
  struct PointFrame {
    // The point as each body carries it, body frame [m]; for a sphere or capsule, the point of
    // its core (centre or axis) under the contact, and the surface point is roundA / roundB
    // beyond it in world frame: turning a ball about its centre does not move its surface, so
    // its contact point must not turn with it (a rotated anchor lifts a rolling ball off the
    // ground within a substep, and friction then brakes it).
    Vec3 localA = Vec3::Zero(), localB = Vec3::Zero();
    Vec3 roundA = Vec3::Zero(), roundB = Vec3::Zero();  // world [m]; zero for other shapes
    double baseSeparation = 0.0;     // s0 - n . (r_B - r_A) [m]
    bool split = false;  // recycled: each body pushes at its own copy (ContactPoint::offset)
  };
  // 112 bytes like Point (1.75 cache lines): four vectors (96), the base separation, the flag.
  static_assert(sizeof(PointFrame) == 112, "PointFrame's size: see the comment above");
  struct PointReport {
    Vec3 position = Vec3::Zero();    // the manifold's point, world [m]
    double depth = 0.0;              // the manifold's depth [m]
    double relativeVelocity = 0.0;   // u_rel,N before the step [m/s]
    double impactSpeed = 0.0;        // |u_rel,N| when the surfaces meet (restitution) [m/s]
    // Applied over the step: the impulses a substep applies add up to the accumulated ones it
    // ends with (the warm start applies the last substep's, each sweep its change), so they are
    // added once a substep, after the relax sweep, plus the collision and restitution passes.
    double totalNormalImpulse = 0.0;  // [N s]
    Vec3 totalFriction = Vec3::Zero();  // world [N s]
    bool sliding = false;  // slipping at the end of the last step (seed 000's regime, friction_law.h)
    // The restitution pass's share of the impact, and the friction it brought (applyRestitution).
    double bounceImpulse = 0.0;  // [N s]
    Eigen::Vector2d bounceFriction = Eigen::Vector2d::Zero();  // along t1, t2 [N s]
  };
  // 112 bytes (1.75 cache lines), bounceFriction aligned to 16: read at the step's start and end.
  static_assert(sizeof(PointReport) == 112, "PointReport's size: see the comment above");
  struct Constraint {  // one manifold
    int a = 0, b = 0;  // body slots; 0 is the ground
    Vec3 normal = Vec3::UnitY(), tangent1 = Vec3::UnitX(), tangent2 = Vec3::UnitZ();
    double staticFriction = 0.0, kineticFriction = 0.0;  // mu_s, mu_k [1]
    double restitution = 0.0;  // [1]
    double normalAcceleration = 0.0;  // n . (a_B - a_A) from the applied forces (gravity) [m/s^2]
    Softness softness;
    bool sticking = true;      // this step's regime: the last step ended without slipping
    bool slipping = false;     // the patch ended the step slipping (then mu_k next step)
    bool touched = false;      // a point pushed while the surfaces met (s <= 0): a collision
    std::size_t firstPoint = 0, pointCount = 0;
    std::size_t contact = 0;   // index into the contacts
    std::uint64_t key = 0;     // pairKey
  };
  // 176 bytes, 2.75 cache lines: the slots (8), three unit vectors (72), the materials and the
  // normal acceleration (32), the softness (24), the flags, the point range, the contact and the
  // key (40). Each sweep reads its manifold's once for all its points.
  static_assert(!kStatedLayout || sizeof(Constraint) == 176, "Constraint's size: see the comment above");
  struct Cached {  // one manifold of the last step
    std::uint64_t key = 0;
    int count = 0;
    std::array<Vec3, kMaxManifoldPoints> localPoints{};  // body B's frame [m]
    std::array<double, kMaxManifoldPoints> normalImpulses{};
    std::array<Vec3, kMaxManifoldPoints> frictionImpulses{};  // world [N s]
    std::array<bool, kMaxManifoldPoints> sliding{};  // seed000: per point
    bool sticking = true;
  };
  // 248 bytes, under 4 cache lines: the key and count (16), four points and four frictions (192),
  // four impulses (32), the flags. Read once a step per manifold, to warm start it.
  static_assert(sizeof(Cached) == 248, "Cached's size: see the comment above");

  struct JointConstraint {  // one joint this step
    std::size_t joint = 0;  // index into the joints
    int base = 0, moving = 0;  // slots; 0 is the ground
    Vec3 localAnchorBase = Vec3::Zero();  // in the slot's frame (world for the ground) [m]
    Vec3 localAnchorMoving = Vec3::Zero();
    Vec3 localAxisBase = Vec3::UnitZ();
    Vec3 localAxisMoving = Vec3::UnitZ();
    Quat baseOrientation = Quat::Identity();  // of a base without a slot, for the hinge angle
    Joint* data = nullptr;  // definition and accumulated impulses
    // Index into jointExtras_ for a joint with more than a plain ball's or hinge's rows (a spring,
    // friction, ball limits, prismatic, weld), else -1: plain joints read nothing more.
    int extra = -1;
    // The joint's type, here so that a plain ball joint's sweep reads only its impulses from
    // the Joint (19701 of them on Box3D's joint grid).
    JointDef::Type type = JointDef::Type::Ball;
  };
  // 160 bytes, 2.5 cache lines: the indices (16), four vectors (96), the base's orientation
  // aligned to 16 (32), the pointer, the extra's index and the type. The sweeps read it every
  // substep; a plain ball joint reads nothing else but its Joint's impulses.
  static_assert(sizeof(JointConstraint) == 160, "JointConstraint's size: see the comment above");

  int slot(const std::vector<RigidBody>& bodies, std::size_t body, const Settings& settings, bool addGravity);
  void prepare(const std::vector<RigidBody>& bodies, const Contact& contact, std::size_t index, std::uint64_t key,
               const Material& material, const Settings& settings);
  const Cached* cached(std::uint64_t key) const;
  void indexCache();  // cacheIndex_ for cache_ as it now is
  // Seed 000's regime at a collision (a point approaching faster than
  // Settings::restitutionThreshold): sliding when the sticking impulse leaves the mu_s cone
  // (collisionImpulse, dynamics/impulse.h). Empty for a resting point, which keeps the regime its
  // last step ended in (a new one first assumes sticking).
  std::optional<bool> seedSlides(const Vec3& anchorA, const Vec3& anchorB, const Constraint& c, const SolverState& stateA,
                  const SolverState& stateB, const Material& material, const Settings& settings) const;
  // The point's arms and separation at the current poses (every substep); with `masses`, its
  // effective masses too (once a step, at prepare: Box2D v3 and Box3D keep them for the step).
  void updateArms(const Constraint& c, const PointFrame& f, Point& p, bool masses) const;
  // u_rel,N at point p of constraint c, body 1 = B, with the arms now.
  double normalVelocity(const Constraint& c, const Point& p, const SolverState& A, const SolverState& B) const {
    return c.normal.dot(B.linearVelocity + B.angularVelocity.cross(p.anchorB) - A.linearVelocity -
                        A.angularVelocity.cross(p.anchorA));
  }
  // Impulse j on B at point p of constraint c, -j on A, with the arms now.
  void applyImpulse(const Constraint& c, const Point& p, const Vec3& j, SolverState& A, SolverState& B) const {
    if (c.a != 0) {
      A.linearVelocity -= sims_[c.a].inverseMass * j;
      A.angularVelocity -= sims_[c.a].inverseInertiaNow * p.anchorA.cross(j);
    }
    if (c.b != 0) {
      B.linearVelocity += sims_[c.b].inverseMass * j;
      B.angularVelocity += sims_[c.b].inverseInertiaNow * p.anchorB.cross(j);
    }
  }
  void integrateVelocities(double h);
  // Island k's share of a substep (solver_islands.h): the sweeps below run island by island.
  void warmStart(std::size_t island);
  void solve(std::size_t island, double inverseH, const Settings& settings, bool useBias, bool lastRelax);
  // The normal impulses of one constraint on the pair's velocities, before its friction.
  void solveNormals(Constraint& c, double inverseH, const Settings& settings, bool useBias, bool lastRelax, Vec3& vA,
                    Vec3& wA, Vec3& vB, Vec3& wB);
  // A sweep's velocities of slot `slot` written back, unless it is the ground (slot 0, never
  // written): the one write-back of the contact sweeps and the joints.
  void storeVelocities(int slot, const Vec3& v, const Vec3& w) {
    if (slot == 0) return;
    states_[slot].linearVelocity = v;
    states_[slot].angularVelocity = w;
  }
  // f(k) for every island k, on Settings::threads threads when the step is large enough to pay
  // for waking them.
  template <typename F>
  void forEachIsland(F&& f) const {
    parallelForUneven(islands_.count(), threads_, constraints_.size() + joints_.size() >= detail::minParallelItems(), f);
  }
  void integratePositions(double h);
  void collide(const Settings& settings, double h);  // single-point collisions within the substep h
  void applyRestitution(const Settings& settings);
  void finish(std::vector<RigidBody>& bodies);
  void report() const;  // solved_ from this step's constraints
  // soft_step_joints.cpp
  // The joints name their bodies by id, resolved to indices through `bodyIds` here, where they are read.
  void slotJoints(const std::vector<RigidBody>& bodies, const IdTable<BodyId>& bodyIds, std::vector<Joint>& joints,
                  const Settings& settings, bool addGravity);
  void prepareJoints(const std::vector<RigidBody>& bodies, const IdTable<BodyId>& bodyIds, std::vector<Joint>& joints,
                     const Settings& settings);
  void warmStartJoints(std::size_t island);
  void solveJoints(std::size_t island, double h, bool useBias);

  std::vector<SolverState> states_;  // per slot
  std::vector<BodySim> sims_;      // per slot
  // The body's own inertias per slot, copied so that integratePositions, every substep, reads no
  // RigidBody (a cache miss per body: 12 % of Box3D's rain went there), and apart from BodySim,
  // which the sweeps read.
  struct BodyInertia {
    Mat3 inertia = Mat3::Zero(), inverse = Mat3::Zero();  // body frame
  };
  std::vector<BodyInertia> inertias_;  // per slot
  // Per slot: R and x now, for the separations (integratePositions); apart from the states, so
  // that updateArms reads two cache lines a body instead of four.
  struct Pose {
    Mat3 rotation = Mat3::Identity();
    Vec3 position = Vec3::Zero();  // [m]
  };
  std::vector<Pose> poses_;
  // Constraint::contact of a contact that slept after the solve (contactsReindexed): not reported.
  static constexpr std::size_t kNotReported = kDroppedContact;
  std::vector<Constraint> constraints_;
  std::vector<std::size_t> bouncing_;  // the constraints collide() looks at: one point, c_R > 0
  std::vector<Point> points_;
  std::vector<PointFrame> frames_;    // per point
  std::vector<PointReport> reports_;  // per point
  std::vector<int> slotOfBody_;    // per World body: its slot, or 0
  std::vector<char> advanced_;     // per World body
  std::vector<std::size_t> advancedList_;
  mutable std::vector<SolvedContactPoint> solved_;
  mutable bool reported_ = true;  // solved_ is this step's (or there is no step to report)
  std::vector<ContactHit> hits_;  // the last solve's, in constraint (contact) order
  double hitSpeed_ = 0.0;         // Settings::hitEventSpeed of the last solve [m/s]
  std::vector<Cached> cache_, nextCache_;  // sorted by key
  KeyIndex cacheIndex_;  // cache_'s entries by key (cached()), rebuilt by indexCache()
  // The warm starts of sleeping contacts (contactsSlept), by key, until they wake.
  // A hash map: a removal or a wake looks up a few of a resting pile's tens of thousands in one
  // probe each, where an ordered map's tree walk missed the cache at each level.
  std::unordered_map<std::uint64_t, Cached> asleepCache_;
  void mergeAsleep(std::vector<Cached>& into) const;  // into a list sorted by key, keys not in it
  Softness softness_;  // of every contact this step
  std::vector<JointConstraint> joints_;
  Softness jointSoftness_;  // of every joint this step
  std::vector<joint_rows::Extra> jointExtras_;  // JointConstraint::extra
  SolverIslands islands_;
  int threads_ = 1;  // Settings::threads of this step
};

}  // namespace rbsim
