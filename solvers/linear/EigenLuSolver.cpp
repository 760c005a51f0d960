#include "solvers/linear/EigenLuSolver.h"

#include <string>

namespace c2d {

Status EigenLuSolver::analyze(const SparseMatrix& A, bool /*symmetric*/) {
  factored_ = false;
  if (Status s = pattern_.record(A); !s) return Status::failure("eigen-lu: " + s.why);
  lu_.analyzePattern(A);
  return Status::success();
}

Status EigenLuSolver::factorize(const SparseMatrix& A) {
  factored_ = false;
  if (Status s = pattern_.check(A); !s) return Status::failure("eigen-lu: " + s.why);
  lu_.factorize(A);
  if (lu_.info() != Eigen::Success) {
    return Status::failure("eigen-lu: matrix is singular (" + lu_.lastErrorMessage() + ")");
  }
  factored_ = true;
  return Status::success();
}

Status EigenLuSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!factored_) return Status::failure("eigen-lu: no valid factorization to solve with");
  const int n = pattern_.size();
  if (b.size() != n || x.size() != n) {
    return Status::failure("eigen-lu: vector sizes " + std::to_string(b.size()) + ", " +
                           std::to_string(x.size()) + " do not match the matrix size " +
                           std::to_string(n));
  }
  if (!b.allFinite()) return Status::failure("eigen-lu: non-finite entry in the right-hand side");
  x = lu_.solve(b);
  if (!x.allFinite()) return Status::failure("eigen-lu: solution is not finite");
  return Status::success();
}

}  // namespace c2d
