#include "solvers/linear/EigenLuSolver.h"

namespace c2d {

Status EigenLuSolver::analyze(const SparseMatrix& A, bool /*symmetric*/) {
  factored_ = false;
  if (Status s = recordPattern(A); !s) return s;
  decomposition_.analyzePattern(A);
  return Status::success();
}

}  // namespace c2d
