#include "dynamics/lcp_pivoting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/QR>

namespace rbsim {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

double largestMagnitude(const VectorXd& x) { return x.size() == 0 ? 0.0 : x.cwiseAbs().maxCoeff(); }

// M restricted to rows and columns `rows`.
MatrixXd principalBlock(const MatrixXd& m, const std::vector<Index>& rows) {
  const Index k = static_cast<Index>(rows.size());
  MatrixXd out(k, k);
  for (Index i = 0; i < k; ++i) {
    for (Index j = 0; j < k; ++j) out(i, j) = m(rows[i], rows[j]);
  }
  return out;
}

// The least-norm solution of M_ZZ f_Z = -q_Z with f zero off Z (lcp_pivoting.h), kept when it
// solves the LCP to kLcpZeroTolerance: f >= 0, w_Z = 0, w >= 0 elsewhere. M is the scaled matrix.
bool leastNormOn(const MatrixXd& m, const VectorXd& q, const std::vector<char>& active, VectorXd& f) {
  const Index n = q.size();
  std::vector<Index> z;
  for (Index i = 0; i < n; ++i) {
    if (active[static_cast<std::size_t>(i)]) z.push_back(i);
  }
  f.setZero(n);
  if (!z.empty()) {
    VectorXd qz(static_cast<Index>(z.size()));
    for (std::size_t i = 0; i < z.size(); ++i) qz(static_cast<Index>(i)) = q(z[i]);
    Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod;
    cod.setThreshold(kLcpRankTolerance);
    cod.compute(principalBlock(m, z));
    const VectorXd fz = cod.solve(-qz);
    for (std::size_t i = 0; i < z.size(); ++i) f(z[i]) = fz(static_cast<Index>(i));
  }
  const VectorXd w = m * f + q;
  const double tolerance = kLcpZeroTolerance * std::max(largestMagnitude(q), largestMagnitude(f));
  for (Index i = 0; i < n; ++i) {
    if (f(i) < -tolerance) return false;
    if (active[static_cast<std::size_t>(i)] ? std::abs(w(i)) > tolerance : w(i) < -tolerance) return false;
  }
  f = f.cwiseMax(0.0);
  return true;
}

// The Cholesky factor L L^T = M_CC of the clamped set, kept up to date as points join and leave
// rather than computed afresh at each pivot: a point joins as a new last row (its Schur
// complement is the new diagonal's square), a point leaves by deleting its row and turning the
// lower Hessenberg rest back into a triangle with Givens rotations on the columns; each costs
// O(k^2) where a new factorization costs O(k^3) (Golub and Van Loan, "Matrix Computations", 4th ed.,
// section 6.5, updating matrix factorizations).
class ClampedFactor {
  MatrixXd l_;  // L in its top-left k x k corner
  Index k_ = 0;
  auto lower() const { return l_.topLeftCorner(k_, k_).triangularView<Eigen::Lower>(); }

 public:
  explicit ClampedFactor(Index capacity) : l_(MatrixXd::Zero(capacity, capacity)) {}
  // y = L^-1 v: M_jC M_CC^-1 M_Cj = |y|^2 for v = M_Cj.
  VectorXd forward(const VectorXd& v) const { return lower().solve(v); }
  // x = M_CC^-1 v = L^-T L^-1 v.
  VectorXd solve(const VectorXd& v) const {
    return l_.topLeftCorner(k_, k_).transpose().triangularView<Eigen::Upper>().solve(forward(v));
  }
  // A point with column `column` = M_Cj and diagonal M_jj joins C, unless its Schur complement is
  // rounding (kLcpSchurTolerance): then false, and nothing changes.
  bool append(const VectorXd& column, double diagonal) {
    const VectorXd y = forward(column);
    const double schur = diagonal - y.squaredNorm();
    if (!(schur > kLcpSchurTolerance)) return false;
    l_.row(k_).head(k_) = y.transpose();
    l_(k_, k_) = std::sqrt(schur);
    ++k_;
    return true;
  }
  // The point at position p of C leaves.
  void remove(Index p) {
    for (Index i = p; i + 1 < k_; ++i) l_.row(i).head(k_) = l_.row(i + 1).head(k_);
    --k_;
    // Row i >= p now reaches column i + 1: rotate columns i and i + 1 to zero it.
    for (Index i = p; i < k_; ++i) {
      const double a = l_(i, i), b = l_(i, i + 1), r = std::hypot(a, b);
      if (r == 0.0) continue;
      const double c = a / r, s = b / r;
      for (Index row = i; row < k_; ++row) {
        const double x = l_(row, i), y = l_(row, i + 1);
        l_(row, i) = c * x + s * y;
        l_(row, i + 1) = c * y - s * x;
      }
    }
  }

};

// Dantzig's principal pivoting in Baraff's form (lcp_pivoting.h) on the scaled problem; leaves
// the pivoting's solution in f and its clamped set in `clamped`.
LcpSolution::Status pivoting(const MatrixXd& m, const VectorXd& q, VectorXd& f, std::vector<char>& clamped,
                             int& pivots) {
  const Index n = q.size();
  enum : char { kUndriven = 0, kClamped = 1, kSeparated = 2 };  // C: w = 0, f >= 0; separated: f = 0, w >= 0
  std::vector<char> state(static_cast<std::size_t>(n), kUndriven);
  std::vector<Index> set;  // C, in the order of the factor's rows
  ClampedFactor factor(n);
  f.setZero(n);
  VectorXd w = q, df(n);
  const double zero = kLcpZeroTolerance * largestMagnitude(q);
  const int cap = kMaxLcpPivotsPerRow * static_cast<int>(n);
  const auto column = [&](Index j) {  // M_Cj
    VectorXd out(static_cast<Index>(set.size()));
    for (std::size_t i = 0; i < set.size(); ++i) out(static_cast<Index>(i)) = m(set[i], j);
    return out;
  };
  // f on C from the invariant w_C = 0, M_CC f_C = -(q_C + M_Cd f_d) with f_d held, and w from f:
  // recomputed after every pivot rather than carried, so rounding does not accumulate.
  const auto settle = [&](Index d, double drive) {
    f.setZero();
    if (d >= 0) f(d) = drive;
    VectorXd rhs(static_cast<Index>(set.size()));
    for (std::size_t i = 0; i < set.size(); ++i) {
      rhs(static_cast<Index>(i)) = -q(set[i]) - (d >= 0 ? m(set[i], d) * drive : 0.0);
    }
    const VectorXd fc = factor.solve(rhs);
    w = q;
    if (d >= 0) w += drive * m.col(d);
    for (std::size_t i = 0; i < set.size(); ++i) {
      f(set[i]) = fc(static_cast<Index>(i));
      w += f(set[i]) * m.col(set[i]);  // M f over the columns where f is not 0: O(n k)
    }
  };
  for (;;) {
    // The most negative w among the points not yet driven (Baraff: any of them).
    Index d = -1;
    for (Index i = 0; i < n; ++i) {
      if (state[static_cast<std::size_t>(i)] == kUndriven && w(i) < -zero && (d < 0 || w(i) < w(d))) d = i;
    }
    if (d < 0) break;  // the rest stay at f = 0 with w >= 0
    for (;;) {
      if (++pivots > cap) return LcpSolution::Status::PivotLimit;
      // The direction: df_d = 1, df_C = -M_CC^-1 M_Cd (so that w_C stays 0), dw = M df.
      df.setZero();
      df(d) = 1.0;
      const VectorXd dc = factor.solve(-column(d));
      VectorXd dw = m.col(d);
      for (std::size_t i = 0; i < set.size(); ++i) {
        df(set[i]) = dc(static_cast<Index>(i));
        dw += df(set[i]) * m.col(set[i]);
      }
      const double floor = kLcpDirectionTolerance * std::max(1.0, largestMagnitude(df));
      // A separated point j joins C only if it does not depend on C: its Schur complement
      // M_jj - M_jC M_CC^-1 M_Cj, quadratic in how far its row is from C's span, is not rounding.
      // One that depends on C follows it (w_j = 0 with w_C, to the data's rounding) and needs no f.
      const auto independent = [&](Index j) {
        return m(j, j) - factor.forward(column(j)).squaredNorm() > kLcpSchurTolerance;
      };
      // The largest step that keeps every f of C and every w of the separated set >= 0 (Baraff's
      // maxstep); w_d reaching 0 ends the drive.
      double step = std::numeric_limits<double>::infinity();
      Index limit = -1;
      if (dw(d) > floor) {
        step = std::max(-w(d), 0.0) / dw(d);
        limit = d;
      }
      for (Index i = 0; i < n; ++i) {
        const char s = state[static_cast<std::size_t>(i)];
        const double reach = s == kClamped && df(i) < -floor      ? std::max(f(i), 0.0) / -df(i)
                             : s == kSeparated && dw(i) < -floor ? std::max(w(i), 0.0) / -dw(i)
                                                                 : step;
        if (reach < step && (s == kClamped || independent(i))) {
          step = reach;
          limit = i;
        }
      }
      if (limit < 0) return LcpSolution::Status::NoSolution;  // w_d can never reach 0
      const double drive = f(d) + step;
      if (state[static_cast<std::size_t>(limit)] == kClamped) {  // its f reached 0: it separates
        state[static_cast<std::size_t>(limit)] = kSeparated;
        const auto at = std::find(set.begin(), set.end(), limit);
        factor.remove(at - set.begin());
        set.erase(at);
        settle(d, drive);
        continue;
      }
      // w_d reached 0 (the drive ends), or a separated point's w did (it pushes from now on).
      if (!factor.append(column(limit), m(limit, limit))) return LcpSolution::Status::NoSolution;
      state[static_cast<std::size_t>(limit)] = kClamped;
      set.push_back(limit);
      if (limit == d) {
        settle(-1, 0.0);
        break;
      }
      settle(d, drive);
    }
  }
  clamped.assign(static_cast<std::size_t>(n), 0);
  for (Index i : set) clamped[static_cast<std::size_t>(i)] = 1;
  return LcpSolution::Status::Solved;
}

// f from the guess that the points `set` push and no other: M_SS f_S = -q_S, kept when it solves
// the LCP to kLcpZeroTolerance (f >= 0, w_S = 0, w >= 0 elsewhere).
bool solveOn(const MatrixXd& m, const VectorXd& q, const std::vector<char>& set, VectorXd& f) {
  std::vector<Index> s;
  for (Index i = 0; i < q.size(); ++i) {
    if (set[static_cast<std::size_t>(i)]) s.push_back(i);
  }
  f.setZero(q.size());
  if (!s.empty()) {
    VectorXd rhs(static_cast<Index>(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) rhs(static_cast<Index>(i)) = -q(s[i]);
    const VectorXd fs = principalBlock(m, s).ldlt().solve(rhs);
    for (std::size_t i = 0; i < s.size(); ++i) f(s[i]) = fs(static_cast<Index>(i));
  }
  const VectorXd w = m * f + q;
  const double tolerance = kLcpZeroTolerance * std::max(largestMagnitude(q), largestMagnitude(f));
  for (Index i = 0; i < q.size(); ++i) {
    if (!std::isfinite(f(i)) || f(i) < -tolerance) return false;
    if (set[static_cast<std::size_t>(i)] ? std::abs(w(i)) > tolerance : w(i) < -tolerance) return false;
  }
  f = f.cwiseMax(0.0);
  return true;
}

}  // namespace

LcpSolution solveLcp(const MatrixXd& a, const VectorXd& b, const std::vector<char>* guess, bool leastNorm) {
  const Index n = b.size();
  LcpSolution out;
  out.f.setZero(n);
  out.w = b;
  out.active.assign(static_cast<std::size_t>(n), 0);
  out.clamped.assign(static_cast<std::size_t>(n), 0);
  if (n == 0) return out;
  // Scaled to a unit diagonal, M = D A D, q = D b, f = D f' (D = diag(A)^-1/2), so that the
  // tolerances compare like with like whatever the masses and lever arms.
  const VectorXd d = a.diagonal().cwiseSqrt().cwiseInverse();
  const MatrixXd m = d.asDiagonal() * a * d.asDiagonal();
  const VectorXd q = d.cwiseProduct(b);
  VectorXd f;
  if (q.minCoeff() >= 0.0) {  // nothing approaches: f = 0
    for (Index i = 0; i < n; ++i) out.active[static_cast<std::size_t>(i)] = q(i) == 0.0;
    return out;
  }
  if (guess != nullptr && guess->size() == static_cast<std::size_t>(n) && solveOn(m, q, *guess, f)) {
    out.clamped = *guess;
  } else {
    out.status = pivoting(m, q, f, out.clamped, out.pivots);
    if (out.status != LcpSolution::Status::Solved) return out;
  }
  // Z: the clamped points and any other at w = 0; its least-norm solution if it is one.
  const VectorXd w = m * f + q;
  const double zero = kLcpZeroTolerance * std::max(largestMagnitude(q), largestMagnitude(f));
  for (Index i = 0; i < n; ++i) {
    out.active[static_cast<std::size_t>(i)] = out.clamped[static_cast<std::size_t>(i)] || std::abs(w(i)) <= zero;
  }
  VectorXd shortest;
  f = leastNorm && leastNormOn(m, q, out.active, shortest) ? shortest : VectorXd(f.cwiseMax(0.0));
  out.f = d.cwiseProduct(f);
  out.w = a * out.f + b;
  return out;
}

}  // namespace rbsim
