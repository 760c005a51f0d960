#include "solvers/linear/EigenLdltSolver.h"

#include <string>

namespace c2d {

Status EigenLdltSolver::analyze(const SparseMatrix& A, bool symmetric) {
  factored_ = false;
  pattern_.clear();
  if (!symmetric)
    return Status::failure("eigen-ldlt: an LDLT factorization needs a symmetric matrix");
  if (Status s = pattern_.record(A); !s) return Status::failure("eigen-ldlt: " + s.why);
  ldlt_.analyzePattern(A);
  if (ldlt_.info() != Eigen::Success) {
    pattern_.clear();
    return Status::failure("eigen-ldlt: symbolic analysis failed");
  }
  return Status::success();
}

Status EigenLdltSolver::factorize(const SparseMatrix& A) {
  factored_ = false;
  if (Status s = pattern_.check(A); !s) return Status::failure("eigen-ldlt: " + s.why);
  ldlt_.factorize(A);
  if (ldlt_.info() != Eigen::Success) {
    return Status::failure("eigen-ldlt: matrix is singular (zero pivot in D)");
  }
  factored_ = true;
  return Status::success();
}

Status EigenLdltSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!factored_) return Status::failure("eigen-ldlt: no valid factorization to solve with");
  const int n = pattern_.size();
  if (b.size() != n || x.size() != n) {
    return Status::failure("eigen-ldlt: vector sizes " + std::to_string(b.size()) + ", " +
                           std::to_string(x.size()) + " do not match the matrix size " +
                           std::to_string(n));
  }
  if (!b.allFinite()) return Status::failure("eigen-ldlt: non-finite entry in the right-hand side");
  x = ldlt_.solve(b);
  if (!x.allFinite()) return Status::failure("eigen-ldlt: solution is not finite");
  return Status::success();
}

}  // namespace c2d
