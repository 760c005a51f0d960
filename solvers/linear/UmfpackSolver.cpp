#include "solvers/linear/UmfpackSolver.h"

#include <umfpack.h>

#include <algorithm>
#include <string>

namespace c2d {

namespace {
std::string umfpackError(const char* what, int status) {
  std::string s = std::string("umfpack: ") + what + " failed";
  switch (status) {
    case UMFPACK_ERROR_out_of_memory:
      return s + " (out of memory)";
    case UMFPACK_ERROR_invalid_matrix:
      return s + " (invalid matrix)";
    case UMFPACK_ERROR_different_pattern:
      return s + " (pattern differs from the analysis)";
    default:
      return s + " (status " + std::to_string(status) + ")";
  }
}
}  // namespace

UmfpackSolver::UmfpackSolver() : control_(UMFPACK_CONTROL), info_(UMFPACK_INFO) {
  umfpack_di_defaults(control_.data());
  control_[UMFPACK_PRL] = 0;  // failures are returned as Status, never printed
}

UmfpackSolver::~UmfpackSolver() {
  freeNumeric();
  freeSymbolic();
}

void UmfpackSolver::freeSymbolic() {
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void UmfpackSolver::freeNumeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
  factored_ = false;
}

Status UmfpackSolver::analyze(const SparseMatrix& A, bool symmetric) {
  freeNumeric();
  freeSymbolic();
  if (Status s = recordPattern(A); !s) return s;
  if (!pattern_.sorted()) {
    pattern_.clear();
    return Status::failure("umfpack: row indices must be sorted within each column");
  }
  const int n = pattern_.size();
  values_.assign(A.valuePtr(), A.valuePtr() + A.nonZeros());
  rhsCopy_.assign(static_cast<size_t>(n), 0.0);
  intWork_.assign(static_cast<size_t>(n), 0);
  // 5n doubles: what umfpack_di_wsolve needs with iterative refinement on.
  work_.assign(static_cast<size_t>(5) * static_cast<size_t>(n), 0.0);
  control_[UMFPACK_STRATEGY] = symmetric ? UMFPACK_STRATEGY_SYMMETRIC : UMFPACK_STRATEGY_AUTO;
  const int status = umfpack_di_symbolic(n, n, pattern_.outer(), pattern_.inner(), values_.data(),
                                         &symbolic_, control_.data(), info_.data());
  if (status != UMFPACK_OK) {
    freeSymbolic();
    pattern_.clear();
    return Status::failure(umfpackError("symbolic analysis", status));
  }
  return Status::success();
}

Status UmfpackSolver::factorize(const SparseMatrix& A) {
  freeNumeric();
  if (!symbolic_) return Status::failure("umfpack: factorize() before analyze()");
  if (Status s = checkPattern(A); !s) return s;
  std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), values_.begin());
  const int status = umfpack_di_numeric(pattern_.outer(), pattern_.inner(), values_.data(),
                                        symbolic_, &numeric_, control_.data(), info_.data());
  if (status == UMFPACK_WARNING_singular_matrix) {
    // The factors exist but U has a zero on its diagonal: solving would divide by zero.
    freeNumeric();
    return Status::failure("umfpack: matrix is singular (zero pivot in U)");
  }
  if (status != UMFPACK_OK) {
    freeNumeric();
    return Status::failure(umfpackError("numeric factorization", status));
  }
  factored_ = true;
  return Status::success();
}

Status UmfpackSolver::solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const int n = pattern_.size();
  // UMFPACK needs distinct right-hand side and solution arrays.
  const double* rhs = b.data();
  if (rhs == x.data()) {
    std::copy(b.data(), b.data() + n, rhsCopy_.begin());
    rhs = rhsCopy_.data();
  }
  const int status = umfpack_di_wsolve(UMFPACK_A, pattern_.outer(), pattern_.inner(),
                                       values_.data(), x.data(), rhs, numeric_, control_.data(),
                                       info_.data(), intWork_.data(), work_.data());
  if (status != UMFPACK_OK) return Status::failure(umfpackError("solve", status));
  return Status::success();
}

}  // namespace c2d
