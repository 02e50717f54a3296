#pragma once
// The exact reference contact solver (Settings::solver = lcp, issue 55; contact_solver.h) for
// small scenes: seed 001 "Resting Contact" as the seed poses it, the normal impulses of all
// contact points of an island found at once as a quadratic program, i.e. the linear
// complementarity problem
//   w = A f + b,  f >= 0 (repulsive),  w >= 0 (no interpenetration),  f.w = 0 (complementary),
// solved exactly by Dantzig's principal pivoting method (lcp_pivoting.h), where PGS iterates
// towards it. At the velocity level of an impulse solver: A = J M^-1 J^T, the Delassus matrix
// over the island's normal rows; b the relative normal velocities the step reaches without
// contact impulses, less each point's target (-c_R u for a collision, a speculative gap's closing
// speed, else 0); so w is the relative normal velocity after the step above its target, and f
// the normal impulses [N s].
//
// The step is the velocity-level one of Catto (GDC 2005): integrate velocities with the forces,
// solve the contact impulses, integrate positions with the velocities found (symplectic Euler).
// World collides first, at the poses the last step left (Order::CollideFirst, as the soft step),
// and this solver advances every awake dynamic body it finds in contact over the whole step; the
// integrator advances the rest. So a resting body ends each step exactly at rest, where it began
// (in PGS's order, integrate first, the integrator's g dt^2 terms move it each step: on a 20
// degree slope a box crept 2.8 cm in a second at 1/60 s). The rows are built as PGS builds them
// (pgs_solver.cpp), speculative points included. Penetration beyond the slop is taken out by
// split impulses that move positions and add no energy (Catto, GDC 2009), here an exact LCP
// too, with the same A.
//
// Friction is not part of the exact solve. It is PGS's cone at each manifold's centroid with a
// twist about the normal (pgs_solver.h), warm started from the last step, swept by projected
// Gauss-Seidel with the normal impulses held fixed, alternated with exact normal solves until it
// stops changing (a block Gauss-Seidel of at most kMaxLcpFrictionPasses passes). The last solve
// of a step is a normal one, so seed 001's conditions hold exactly for the friction the step ends
// with; that friction lies in the cone of the normal impulses of the pass before.
// Settings::friction = seed000 is refused with this solver (checkSettings). Each exact solve
// first tries the points that pushed in the solve before (the last pass, or the last step, found
// by their place on body 1 as PGS's warm start finds its points): when they solve it, nothing
// pivots, which at rest is every solve.
//
// Split impulses whose LCP has no solution (a body wedged between fixed ones, penetrating both)
// leave the positions uncorrected for the step; the velocities' LCP without a solution is an error.
//
// Islands (bodies linked through dynamic-dynamic contacts; static and kinematic bodies link
// nothing) are independent problems. An island of more than kMaxLcpRows normal rows is refused
// at step time with a SimulationError naming world.solver: the rows are known only once the
// bodies touch.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/contact_solver.h"
#include "dynamics/lcp_pivoting.h"

namespace rbsim {

// Normal rows (contact points) of one island in one dense solve: A alone holds n^2 doubles
// (2.9 MB at 600), a step's decompositions cost O(n^3), and a pyramid of 55 boxes (580 rows)
// already takes about 0.1 s a step; PGS and the soft step are for anything larger.
inline constexpr std::size_t kMaxLcpRows = 600;  // [rows]
// Friction passes (a friction sweep, then an exact normal solve) per island and step at most;
// a resting patch settles in a few, a box held on a slope in some tens.
inline constexpr int kMaxLcpFrictionPasses = 100;  // [passes]
// The passes stop once no friction impulse changed by more than this fraction of the island's
// largest normal impulse, or once the change is no smaller than two passes before (rounding's
// floor: a 55-box pyramid's friction settles near 1e-12, not below).
inline constexpr double kLcpFrictionTolerance = 1e-13;  // [1]

class LcpSolver final : public ContactSolver {
 public:
  Order order() const override { return Order::CollideFirst; }
  bool solvesJoints() const override { return false; }
  // Advances by settings.timeStep every awake dynamic body in a contact with a manifold (x, q, P,
  // L), using the forces and torques accumulated in it, plus m g when `addGravity`; clears their
  // accumulators. Throws SimulationError for an island beyond kMaxLcpRows, a velocity problem
  // with no solution (a body crushed between static or kinematic ones) or the pivoting beyond
  // its pivot cap.
  void solve(const SolverInput& input) override;
  std::unique_ptr<ContactSolver> clone() const override { return std::make_unique<LcpSolver>(*this); }
  const std::vector<SolvedContactPoint>& points() const override { return solved_; }
  void contactsReindexed(const std::vector<std::uint32_t>& newIndex) override { reindexPoints(solved_, newIndex); }
  void forget() override {
    clearAdvanced();
    cache_.clear();
    solved_.clear();
  }
  void bodiesRemoved(const std::vector<std::uint32_t>& removed, const std::vector<std::uint64_t>& goneAsleep) override;
  const std::vector<std::size_t>& advancedBodies() const override { return advancedList_; }
  const std::vector<char>& advancedFlags() const override { return advanced_; }  // per World body
  void clearAdvanced() override {
    for (std::size_t body : advancedList_) advanced_[body] = 0;
    advancedList_.clear();
  }

  // The last solve's figures: the pivots the LCP solves took over all islands and passes, the
  // most friction passes an island took (kMaxLcpFrictionPasses: the friction had not settled),
  // and the largest island's row count.
  int lastPivots() const { return pivots_; }
  int lastFrictionPasses() const { return frictionPasses_; }
  std::size_t largestIsland() const { return largestIsland_; }

 private:
  struct Velocity {
    Vec3 linear = Vec3::Zero();   // v [m/s]
    Vec3 angular = Vec3::Zero();  // omega [rad/s]
  };
  static_assert(sizeof(Velocity) == 48, "v and omega, 4 bodies in 3 cache lines");
  struct SolverBody {  // constant over the step
    double inverseMass = 0.0;  // 0 for static and kinematic bodies and planes
    Mat3 inverseInertiaWorld = Mat3::Zero();
    std::size_t body = 0;  // index into the World's bodies
  };
  static_assert(sizeof(SolverBody) == 88, "1/m, I^-1 (72) and the index: 1.4 cache lines");
  // A normal row: its Jacobian (n, r1 x n; -n, -(r2 x n)) and M^-1 J^T (I^-1 (r x n)).
  struct Row {
    int body1 = 0, body2 = 0;  // indices into bodies_, the patch's
    Vec3 normal = Vec3::UnitY();
    Vec3 angular1 = Vec3::Zero(), angular2 = Vec3::Zero();          // r1 x n, r2 x n [m]
    Vec3 angularStep1 = Vec3::Zero(), angularStep2 = Vec3::Zero();  // I1^-1 (r1 x n), I2^-1 (r2 x n)
    double target = 0.0;         // bounce, speculative closing or 0 [m/s]
    double correction = 0.0;     // split-impulse target [m/s]
    double impulse = 0.0;        // j_N >= 0 [N s]
    double pseudoImpulse = 0.0;  // split impulse [N s]
    char clamped = 0;            // pushing in the pivoting's set C: last step's, then this step's
    Vec3 localPoint1 = Vec3::Zero();  // the point in body 1's frame, to find it next step [m]
  };
  // 192 bytes, 3 cache lines: the bodies (8), six vectors (144), four doubles (32), the flag and
  // 7 of padding. The pivoting reads the rows of an island as its matrix's columns.
  static_assert(sizeof(Row) == 192, "Row's size in cache lines: see the comment above");
  struct Patch {  // one manifold
    int body1 = 0, body2 = 0;  // indices into bodies_
    Vec3 normal = Vec3::UnitY();
    Vec3 tangent1 = Vec3::UnitX(), tangent2 = Vec3::UnitZ();
    Material material;
    std::size_t firstRow = 0, rowCount = 0;
    std::uint64_t key = 0;  // pairKey
    // Friction coordinates at the centroid (t1, t2, twist about n), as PgsSolver::Patch.
    Mat3 angular1 = Mat3::Zero(), angular2 = Mat3::Zero();
    Mat3 angularStep1 = Mat3::Zero(), angularStep2 = Mat3::Zero();
    double twistRadius = 0.0;                 // mean distance of the points from the centroid [m]
    Mat3 inverseFriction = Mat3::Identity();  // (S^T (K_1 + K_2) S)^-1, seed 002
    Vec3 friction = Vec3::Zero();             // (j_t1, j_t2, j_twist) [N s, N s, N m s]
    bool sticking = true;                     // this step's coefficient: mu_s if sticking, else mu_k
    bool insideCone = true;                   // the last sweep's sticking impulse was in the cone
  };
  // 528 bytes, 8.25 cache lines: PgsSolver::Patch and the pair key.
  static_assert(!kStatedLayout || sizeof(Patch) == 528, "Patch's size: see the comment above");
  struct Cached {  // a manifold of the last step, looked up by pair key
    std::uint64_t key = 0;
    bool sticking = true;                // the friction regime of the next step
    Vec3 linearFriction = Vec3::Zero();  // the friction, world, on body 1 [N s]
    double twistFriction = 0.0;          // about the normal [N m s]
    int count = 0;
    std::array<Vec3, kMaxManifoldPoints> localPoints{};  // body 1's frame [m]
    std::array<char, kMaxManifoldPoints> clamped{};      // per point: in C (a guess for the first solve)
  };
  // 160 bytes, 2.5 cache lines: read once a step per manifold.
  static_assert(sizeof(Cached) == 160, "Cached's size: see the comment above");

  int solverBody(const SolverInput& input, std::size_t body);
  void buildPatch(const SolverInput& input, const Contact& contact, std::size_t index);
  double normalVelocity(const Row& row, const std::vector<Velocity>& velocities) const;  // u_rel,N [m/s]
  void applyNormal(const Row& row, double impulse, std::vector<Velocity>& velocities) const;
  void applyFriction(const Patch& patch, const Vec3& impulse);
  double solveFriction(Patch& patch);  // one projected sweep step; returns the change [N s]
  Eigen::MatrixXd delassus(const std::vector<std::size_t>& rows);
  // One exact LCP over `rows` for the impulses `field` (Row::impulse, or Row::pseudoImpulse on
  // the pseudo-velocities) against the targets `target`, applied to `velocities` when solved.
  LcpSolution solveExactly(const Eigen::MatrixXd& a, const std::vector<std::size_t>& rows, double Row::*field,
                           double Row::*target, std::vector<Velocity>& velocities, const std::vector<char>* guess,
                           bool leastNorm);
  // `body`: the name of one of the island's bodies, for the messages.
  void solveIsland(const std::vector<std::size_t>& rows, const std::vector<std::size_t>& patches,
                   const std::string& body);
  void writeBack(std::vector<RigidBody>& bodies, double dt);

  std::vector<SolverBody> bodies_;          // bodies_[0] is the ground: infinite mass, at rest
  std::vector<Velocity> velocities_;        // per entry of bodies_: after the forces, then the impulses
  std::vector<Velocity> pseudoVelocities_;  // split impulse: move x and q, never enter P and L
  std::vector<int> slotOfBody_;             // per World body: index into bodies_, or 0 when untouched
  std::vector<char> advanced_;              // per World body: advanced by the last solve
  std::vector<std::size_t> advancedList_;
  std::vector<Patch> patches_;
  std::vector<Row> rows_;
  std::vector<SolvedContactPoint> solved_;
  std::vector<Cached> cache_;  // last step's manifolds, sorted by key
  std::vector<std::vector<std::pair<std::size_t, double>>> bodyRows_;  // delassus' scratch: (row, sign) per body
  int pivots_ = 0;
  int frictionPasses_ = 0;
  std::size_t largestIsland_ = 0;
};

}  // namespace rbsim
