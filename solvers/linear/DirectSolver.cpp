#include "solvers/linear/DirectSolver.h"

namespace c2d {

Status DirectSolver::failure(const std::string& why) const {
  return Status::failure(name() + ": " + why);
}

Status DirectSolver::recordPattern(const SparseMatrix& A) {
  if (Status s = pattern_.record(A); !s) return failure(s.why);
  return Status::success();
}

Status DirectSolver::checkPattern(const SparseMatrix& A) const {
  if (Status s = pattern_.check(A); !s) return failure(s.why);
  return Status::success();
}

Status DirectSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!factored_) return failure("no valid factorization to solve with");
  const int n = pattern_.size();
  if (b.size() != n || x.size() != n) {
    return failure("vector sizes " + std::to_string(b.size()) + ", " + std::to_string(x.size()) +
                   " do not match the matrix size " + std::to_string(n));
  }
  if (!b.allFinite()) return failure("non-finite entry in the right-hand side");
  if (Status s = solveFactored(b, x); !s) return s;
  if (!x.allFinite()) return failure("solution is not finite");
  return Status::success();
}

}  // namespace c2d
