#include "dynamics/contact_solver.h"

#include "dynamics/lcp_solver.h"
#include "dynamics/pgs_solver.h"
#include "dynamics/soft_step_solver.h"

namespace rbsim {

void ContactSolver::hits(double speed, std::vector<ContactHit>& out) const {
  const std::vector<SolvedContactPoint>& solved = points();
  for (std::size_t k = 0; k < solved.size();) {
    const std::size_t contact = solved[k].contact;
    ContactHit hit{contact, Vec3::Zero(), speed};
    bool found = false;
    for (; k < solved.size() && solved[k].contact == contact; ++k) {
      const SolvedContactPoint& p = solved[k];
      if (-p.approachVelocity > hit.approachSpeed && p.normalImpulse > 0.0) {
        hit.approachSpeed = -p.approachVelocity;
        hit.point = p.position;
        found = true;
      }
    }
    if (found) out.push_back(hit);
  }
}

void ContactSolver::reindexPoints(std::vector<SolvedContactPoint>& points, const std::vector<std::uint32_t>& newIndex) {
  std::size_t kept = 0;
  for (SolvedContactPoint& p : points) {
    const std::uint32_t to = newIndex[p.contact];
    if (to == kDroppedContact) continue;
    p.contact = to;
    points[kept++] = p;
  }
  points.resize(kept);
}

std::unique_ptr<ContactSolver> makeContactSolver(Settings::ContactSolverMethod method) {
  if (method == Settings::ContactSolverMethod::Pgs) return std::make_unique<PgsSolver>();
  if (method == Settings::ContactSolverMethod::Lcp) return std::make_unique<LcpSolver>();
  return std::make_unique<SoftStepSolver>();
}

}  // namespace rbsim
