#pragma once
// An exact solver of the linear complementarity problem (LCP) of seed 001 "Resting Contact": find
// f with w = A f + b, f >= 0 (repulsive), w >= 0 (no interpenetration), f.w = 0 (complementary),
// for a symmetric positive semidefinite A (a Delassus matrix J M^-1 J^T). Dantzig's principal
// pivoting method (Cottle and Dantzig, "Complementary pivot theory of mathematical programming",
// Linear Algebra and its Applications 1, 1968; Cottle, Pang, Stone, "The Linear Complementarity
// Problem", 1992, chapter 4) in the form Baraff gives it for contact forces ("Fast contact force
// computation for nonpenetrating rigid bodies", SIGGRAPH 1994), as ODE's lcp.cpp also does:
// each point with w_d < 0 in turn is driven up, f_d growing while the points already pushing
// (the clamped set C, w_C = 0) follow, until w_d reaches 0 or another point's f or w reaches 0
// and it changes set. A_CC stays nonsingular however many points are redundant (four corners
// under a box, a stack's faces): a point that depends on C changes no w and never joins it.
//
// Each step solves with A_CC afresh (LDL^T) and recomputes f_C and w from A and b, so rounding
// does not build up over the steps: Lemke's method (Lemke, Management Science 11, 1965) on an
// updated tableau, tried first, lost feasibility after 175 pivots on a pyramid of 55 boxes (400
// points, A of rank 165) and cycled.
//
// Solutions are not unique when A is singular, but w is: for two solutions,
// (f1 - f2).A(f1 - f2) = (f1 - f2).(w1 - w2) = -f1.w2 - f2.w1 <= 0, so A (f1 - f2) = 0 for a
// symmetric positive semidefinite A. Every solution is therefore zero off Z = {i: w_i = 0} and
// solves A_ZZ f_Z = -b_Z; the answer is the least-norm solution of that system when it is
// nonnegative (a symmetric stack's corners share the load equally), else the pivoting's own.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace rbsim {

// Pivots (changes of a point's set) the method may take on n rows before it gives up: it needs
// about one per pushing point and a few to drop others (195 for the 400 points above); the cap
// only stops a cycle that rounding could let through from hanging a step.
inline constexpr int kMaxLcpPivotsPerRow = 50;  // [pivots per row]
// A velocity or impulse below this fraction of the problem's scale is zero: where a point is
// driven, where the active set is read off, where a guessed one is checked. The problem is scaled
// to a unit diagonal first, and the scale is max(|b|, |f|) in those units.
inline constexpr double kLcpZeroTolerance = 1e-11;  // [1]
// A change of w or f per unit drive below this (times the largest change of f, at least 1) is
// rounding: a driven point whose w it is depends on C (it never joins C), and a point of C or of
// the separated set that it is does not limit the step.
inline constexpr double kLcpDirectionTolerance = 1e-10;  // [1]
// A separated point whose Schur complement against C (unit diagonal: 1 for a point independent
// of C, 0 for one its rows span) is below this depends on C and never joins it. Judged by the
// change of w alone, a corner of a pyramid's face (a row 1e-8 from C's span: a Schur complement
// of 2e-16, a change of w of 2e-9 per unit drive) went in and out of C for ever.
inline constexpr double kLcpSchurTolerance = 1e-12;  // [1]
// Singular values of A_ZZ below this fraction of its largest are its null space (the redundant
// points of a face) in the least-norm solve.
inline constexpr double kLcpRankTolerance = 1e-9;  // [1]

struct LcpSolution {
  enum class Status {
    Solved,
    NoSolution,  // a driven point that nothing stops: no f >= 0 makes w >= 0 (a body crushed between fixed ones)
    PivotLimit,  // more than kMaxLcpPivotsPerRow * n pivots
  };
  Status status = Status::Solved;
  Eigen::VectorXd f;         // f >= 0
  Eigen::VectorXd w;         // A f + b >= 0, f.w = 0 to rounding
  std::vector<char> active;   // per row: w_i = 0 (the set Z above)
  std::vector<char> clamped;  // per row: in the pivoting's C (A_CC nonsingular), a guess for a nearby problem
  int pivots = 0;             // 0 when b >= 0 or `guess` was right
};

// Solves w = A f + b, f >= 0, w >= 0, f.w = 0 for a symmetric positive semidefinite A with a
// positive diagonal. `guess`: the clamped set of a nearby problem (the same island a friction
// pass or a step before); when the points it names pushing and no other solve the LCP, no
// pivoting is done. `leastNorm`: look for the least-norm solution (a decomposition of A_ZZ, the
// costliest part for a large Z), else return the first solution found.
LcpSolution solveLcp(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const std::vector<char>* guess = nullptr,
                     bool leastNorm = true);

}  // namespace rbsim
