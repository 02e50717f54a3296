#pragma once
// The reference contact solver (Settings::solver = pgs; contact_solver.h): every contact of the
// step solved together (seed 001 "Resting Contact": non-penetrating, repulsive, complementary) by
// projected Gauss-Seidel over accumulated impulses
// (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005), warm started from the previous
// step; penetration removed by split impulses, which move positions and add no energy (Catto,
// "Modeling and Solving Constraints", GDC 2009).
//
// Each manifold point has a normal row (seed 000's j = N j_n with restitution). Friction acts on
// the manifold as a whole, at the centroid of its points: a tangential impulse and a twist about
// the normal, coupled through seed 002's 6x6 K; seed 000's rule decides between sticking (inside
// the cone mu_s of the manifold's total normal impulse) and kinetic friction mu_k against the
// slip. A rigid patch slides as a whole, so the cone is the patch's, not each point's. With
// Settings::friction = seed000 friction is each point's instead, through friction_law.h.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dynamics/contact_key.h"
#include "dynamics/contact_solver.h"

namespace rbsim {

class PgsSolver final : public ContactSolver {
 public:
  Order order() const override { return Order::IntegrateFirst; }
  bool solvesJoints() const override { return false; }
  // Changes P and L of the bodies in contact (and x, q where they penetrate beyond the slop).
  void solve(const SolverInput& input) override;
  void save(ByteWriter& out) const override;  // dynamics/solver_snapshot.cpp
  void load(ByteReader& in, const std::vector<std::uint32_t>& bodyKeys, bool keyedByIndex) override;
  std::unique_ptr<ContactSolver> clone() const override { return std::make_unique<PgsSolver>(*this); }
  const std::vector<SolvedContactPoint>& points() const override { return solved_; }
  void contactsReindexed(const std::vector<std::uint32_t>& newIndex) override { reindexPoints(solved_, newIndex); }
  void forget() override {
    cache_.clear();
    solved_.clear();
  }
  void bodiesRemoved(const std::vector<std::uint32_t>& removed, const std::vector<std::uint64_t>& goneAsleep) override;

 private:
  // The velocities a sweep reads and changes, 48 bytes per body (as Box2D's b2BodyState): the
  // sweeps touch nothing else of a body. Also used for the split impulse's pseudo-velocities.
  struct Velocity {
    Vec3 linear = Vec3::Zero();   // v [m/s]
    Vec3 angular = Vec3::Zero();  // omega [rad/s]
  };
  static_assert(sizeof(Velocity) == 48, "v and omega, 4 bodies in 3 cache lines: the comment above");
  struct SolverBody {  // constant over the step
    double inverseMass = 0.0;  // 0 for static bodies and planes
    Mat3 inverseInertiaWorld = Mat3::Zero();
    std::size_t body = 0;      // index into the World's bodies
  };
  // 88 bytes, 1.4 cache lines: 1/m, I^-1 in world frame (72), the index. Read when a patch is built.
  static_assert(sizeof(SolverBody) == 88, "SolverBody's size: see the comment above");
  // A normal row: the Jacobian of u_rel,N (n on the linear velocities, r x n on the angular ones)
  // and I^-1 (r x n), precomputed, so that a sweep's row costs a few dot products (Catto 2005).
  struct NormalRow {
    Vec3 angular1 = Vec3::Zero(), angular2 = Vec3::Zero();  // r1 x n, r2 x n [m]
    Vec3 angularStep1 = Vec3::Zero(), angularStep2 = Vec3::Zero();  // I1^-1 (r1 x n), I2^-1 (r2 x n)
    Vec3 localPoint1 = Vec3::Zero();  // the point in body 1's frame, for warm starting [m]
    double normalMass = 0.0;              // 1 / (N^T K_T N) [kg]
    double targetNormalVelocity = 0.0;    // bounce, speculative closing or 0 [m/s]
    double correctionVelocity = 0.0;      // split-impulse target [m/s]
    double impulse = 0.0;                 // accumulated j_N >= 0 [N s]
    double pseudoImpulse = 0.0;           // accumulated split impulse [N s]
    // Settings::FrictionModel::Seed000: friction per point (friction_law.h).
    Vec3 arm1 = Vec3::Zero(), arm2 = Vec3::Zero();  // r1, r2: the point from each centre of mass [m]
    Vec3 friction = Vec3::Zero();  // accumulated tangential impulse on body 1, world [N s]
    bool sticking = true;          // the last sweep's sticking impulse was inside the mu_s cone
    bool sliding = false;          // slipping at the end of the last step (friction_law.h)
  };
  // 240 bytes, 3.75 cache lines: five vectors (120), five doubles (40), seed 000's arms and
  // friction (72), the flags. A sweep reads and writes the whole row; without seed 000's per-point
  // friction it would be 168 (2.6 lines).
  static_assert(sizeof(NormalRow) == 240, "NormalRow's size: see the comment above");
  struct Patch {  // one manifold
    int body1 = 0, body2 = 0;  // indices into bodies_
    Vec3 normal = Vec3::UnitY();
    Vec3 tangent1 = Vec3::UnitX(), tangent2 = Vec3::UnitZ();
    Material material;
    std::size_t firstRow = 0, rowCount = 0;
    // Friction coordinates (t1, t2 at the centroid of the points, twist about n): their angular
    // Jacobians, columns (r x t1, r x t2, n), and those times I^-1.
    Mat3 angular1 = Mat3::Zero(), angular2 = Mat3::Zero();
    Mat3 angularStep1 = Mat3::Zero(), angularStep2 = Mat3::Zero();
    double twistRadius = 0.0;                 // mean distance of the points from the centroid [m]
    Mat3 inverseFriction = Mat3::Identity();  // (S^T (K_1 + K_2) S)^-1, seed 002
    Vec3 friction = Vec3::Zero();             // accumulated (j_t1, j_t2, j_twist)
    bool sticking = true;                     // this step's regime: mu_s if sticking, else mu_k
    bool insideCone = true;                   // the last sweep's sticking impulse was in the cone
  };
  // 520 bytes, 8.1 cache lines: the friction's four Jacobian matrices and its inverse mass (360)
  // dominate; a sweep reads one patch per manifold, against up to four rows.
  static_assert(!kStatedLayout || sizeof(Patch) == 520, "Patch's size: see the comment above");
  struct Cached {  // one manifold of the last step, looked up by pair key
    std::uint64_t key = 0;
    int count = 0;
    std::array<Vec3, kMaxManifoldPoints> localPoints{};  // body 1's frame [m]
    std::array<double, kMaxManifoldPoints> normalImpulses{};
    Vec3 linearFriction = Vec3::Zero();  // world [N s]
    double twistFriction = 0.0;          // about the normal [N m s]
    bool sticking = true;                // the regime of the next step
    std::array<Vec3, kMaxManifoldPoints> pointFriction{};  // seed000: per point, world [N s]
    std::array<bool, kMaxManifoldPoints> sliding{};        // seed000: per point
  };
  // 288 bytes, 4.5 cache lines: read once a step per manifold to warm start it.
  static_assert(sizeof(Cached) == 288, "Cached's size: see the comment above");

  int solverBody(std::vector<RigidBody>& bodies, std::size_t body);
  const Cached* cached(std::uint64_t key) const;
  void buildPatch(std::vector<RigidBody>& bodies, const Contact& contact, std::size_t index, std::uint64_t key,
                  const Material& material,
                  const Settings& settings);
  double normalVelocity(const Patch& patch, const NormalRow& row) const;  // u_rel,N [m/s]
  void applyNormal(const Patch& patch, const NormalRow& row, double impulse, std::vector<Velocity>& velocities) const;
  void applyFriction(const Patch& patch, const Vec3& impulse);
  double normalImpulse(const Patch& patch) const;  // sum of the patch's accumulated j_N [N s]
  void solveNormal(Patch& patch, NormalRow& row);
  void solveFriction(Patch& patch);
  // Friction at the point by the law of `model` (friction_law.h), and its impulse applied there.
  void solvePointFriction(const Patch& patch, NormalRow& row, Settings::FrictionModel model);
  void applyPointFriction(const Patch& patch, const NormalRow& row, const Vec3& impulse);
  void markSliding();  // seed000: each row's regime for the next step, from its slip now
  void solvePosition(const Patch& patch, NormalRow& row);
  void writeBack(std::vector<RigidBody>& bodies, double dt);
  void remember(const std::vector<Contact>& contacts, const std::vector<std::uint32_t>& bodyKeys);

  std::vector<SolverBody> bodies_;       // bodies_[0] is the ground: infinite mass, at rest
  std::vector<Velocity> velocities_;     // per entry of bodies_
  std::vector<Velocity> pseudoVelocities_;  // split impulse: move x and q, never enter P and L
  std::vector<int> slotOfBody_;          // per World body: index into bodies_, or 0 when untouched
  std::vector<Patch> patches_;
  std::vector<std::size_t> patchContact_;  // per patch: its contact
  std::vector<NormalRow> rows_;
  std::vector<SolvedContactPoint> solved_;
  std::vector<Cached> cache_;  // last step's manifolds, sorted by key
  std::vector<Cached> nextCache_;
  std::vector<Vec3> linearImpulse_, angularImpulse_;  // writeBack's scratch: Delta P, Delta L per body
};

}  // namespace rbsim
