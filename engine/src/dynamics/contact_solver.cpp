#include "dynamics/contact_solver.h"

#include "dynamics/lcp_solver.h"
#include "dynamics/pgs_solver.h"
#include "dynamics/soft_step_solver.h"

namespace rbsim {

std::unique_ptr<ContactSolver> makeContactSolver(Settings::ContactSolverMethod method) {
  if (method == Settings::ContactSolverMethod::Pgs) return std::make_unique<PgsSolver>();
  if (method == Settings::ContactSolverMethod::Lcp) return std::make_unique<LcpSolver>();
  return std::make_unique<SoftStepSolver>();
}

}  // namespace rbsim
