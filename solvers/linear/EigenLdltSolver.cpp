#include "solvers/linear/EigenLdltSolver.h"

namespace c2d {

Status EigenLdltSolver::analyze(const SparseMatrix& A, bool symmetric) {
  factored_ = false;
  pattern_.clear();
  if (!symmetric)
    return Status::failure("eigen-ldlt: an LDLT factorization needs a symmetric matrix");
  if (Status s = recordPattern(A); !s) return s;
  decomposition_.analyzePattern(A);
  if (decomposition_.info() != Eigen::Success) {
    pattern_.clear();
    return Status::failure("eigen-ldlt: symbolic analysis failed");
  }
  return Status::success();
}

}  // namespace c2d
