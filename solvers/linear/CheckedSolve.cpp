#include "solvers/linear/CheckedSolve.h"

#include <cstdio>

namespace c2d {

bool CheckedSolve::refine(LinearSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& R,
                          Eigen::VectorXd& du, Eigen::VectorXd& rho, Eigen::VectorXd& drho) {
  const double scale = R.norm();
  for (int sweep = 0;; ++sweep) {
    rho.noalias() = K * du;
    rho = R - rho;
    misfit = scale > 0 ? rho.norm() / scale : 0.0;
    if (misfit <= kMaxMisfit) return true;
    if (sweep == kRefinements || !(misfit == misfit)) return false;
    if (drho.size() != du.size()) drho.resize(du.size());
    if (!solver.solve(rho, drho)) return false;
    du += drho;
    ++refinements;
  }
}

Status CheckedSolve::check(LinearSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& R,
                           Eigen::VectorXd& du, Eigen::VectorXd& rho, Eigen::VectorXd& drho) {
  *this = CheckedSolve{};
  if (rho.size() != du.size()) rho.resize(du.size());
  if (refine(solver, K, R, du, rho, drho)) return Status::success();
  if (solver.refactorWithPivoting(K)) {
    pivoted = true;
    if (solver.solve(R, du) && refine(solver, K, R, du, rho, drho)) return Status::success();
  }
  condition = solver.conditionEstimate(K);
  // Without an estimate the solver's failure to balance R is taken as singular.
  singular = !(condition >= 0 && condition < kSingularCondition);
  return Status::failure("the solve leaves a misfit");
}

std::string CheckedSolve::diagnosis() const {
  char text[320];
  if (singular) {
    char estimate[64] = "";
    if (condition >= 0)
      std::snprintf(estimate, sizeof estimate, "; condition number estimate %.1e", condition);
    std::snprintf(text, sizeof text,
                  "singular tangent: the solve leaves %.2e of the residual unbalanced (a "
                  "mechanism?%s)",
                  misfit, estimate);
  } else {
    std::snprintf(text, sizeof text,
                  "ill-conditioned tangent (condition number estimate %.1e): with pivoting and "
                  "refinement the solve still leaves %.2e of the residual unbalanced: "
                  "stiffnesses that differ by too many orders of magnitude for double precision "
                  "(RESUltant STIFfness)",
                  condition, misfit);
  }
  return text;
}

}  // namespace c2d
