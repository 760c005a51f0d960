#include "solvers/linear/KluSolver.h"

#include <string>

namespace c2d {

namespace {
// A refactorization with the old pivot order is kept only while its reciprocal
// pivot growth (max|A| / max|U| column by column, 1 for a perfectly stable
// factorization) stays above this; below it more than about eight digits
// may be lost and a fresh pivot search is cheaper than a wrong Newton step.
constexpr double kMinPivotRatio = 1e-12;
}  // namespace

KluSolver::KluSolver() {
  klu_defaults(&common_);
  // No row scaling and no input check: the pattern is checked here, and a
  // frame's rows are within a few decades of each other, so scaling does not
  // change the pivot choice the threshold test makes; on the refactorizations
  // of a Newton iteration it cost a fifth of the factorization time.
  common_.scale = -1;
}

KluSolver::~KluSolver() {
  freeNumeric();
  freeSymbolic();
}

void KluSolver::freeSymbolic() {
  if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
  symbolic_ = nullptr;
}

void KluSolver::freeNumeric() {
  if (numeric_) klu_free_numeric(&numeric_, &common_);
  numeric_ = nullptr;
  factored_ = false;
}

Status KluSolver::analyze(const SparseMatrix& A, bool /*symmetric*/) {
  freeNumeric();
  freeSymbolic();
  if (Status s = recordPattern(A); !s) return s;
  symbolic_ = klu_analyze(pattern_.size(), pattern_.outer(), pattern_.inner(), &common_);
  if (!symbolic_) {
    pattern_.clear();
    return Status::failure("klu: symbolic analysis failed (status " +
                           std::to_string(common_.status) + ")");
  }
  return Status::success();
}

Status KluSolver::freshFactor(int* p, int* i, double* x) {
  freeNumeric();
  numeric_ = klu_factor(p, i, x, symbolic_, &common_);
  if (common_.status == KLU_SINGULAR) {
    singular_ = common_.singular_col;
    // With halt_if_singular (the default) KLU has already freed the factors.
    freeNumeric();
    return Status::failure("klu: matrix is singular (zero pivot at column " +
                           std::to_string(common_.singular_col) + ")");
  }
  if (!numeric_ || common_.status != KLU_OK) {
    freeNumeric();
    return Status::failure("klu: numeric factorization failed (status " +
                           std::to_string(common_.status) + ")");
  }
  factored_ = true;
  lastWasRefactor_ = false;
  return Status::success();
}

Status KluSolver::factorize(const SparseMatrix& A) {
  factored_ = false;
  singular_ = -1;
  if (!symbolic_) return Status::failure("klu: factorize() before analyze()");
  if (Status s = checkPattern(A); !s) return s;
  // KLU reads but does not write its inputs.
  int* p = const_cast<int*>(A.outerIndexPtr());
  int* i = const_cast<int*>(A.innerIndexPtr());
  double* x = const_cast<double*>(A.valuePtr());
  if (numeric_) {
    // Same pattern, new values: reuse the pivot order and the memory of the
    // factors, unless a pivot vanished or became small with the new values
    // (klu_rcond: the smallest over the largest pivot magnitude, O(n); the
    // pivot growth klu_rgrowth costs a pass over the matrix and the factors).
    if (klu_refactor(p, i, x, symbolic_, numeric_, &common_) && common_.status == KLU_OK &&
        klu_rcond(symbolic_, numeric_, &common_) && common_.rcond >= kMinPivotRatio) {
      factored_ = true;
      lastWasRefactor_ = true;
      return Status::success();
    }
  }
  return freshFactor(p, i, x);
}

bool KluSolver::refactorWithPivoting(const SparseMatrix& A) {
  if (!factored_ || !lastWasRefactor_ || !pattern_.check(A)) return false;
  return static_cast<bool>(freshFactor(const_cast<int*>(A.outerIndexPtr()),
                                       const_cast<int*>(A.innerIndexPtr()),
                                       const_cast<double*>(A.valuePtr())));
}

double KluSolver::conditionEstimate(const SparseMatrix& A) {
  if (!factored_ || !pattern_.check(A)) return -1;
  if (!klu_condest(const_cast<int*>(A.outerIndexPtr()), const_cast<double*>(A.valuePtr()),
                   symbolic_, numeric_, &common_))
    return -1;
  return common_.condest;
}

Status KluSolver::solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const int n = pattern_.size();
  x = b;  // klu_solve works in place
  if (!klu_solve(symbolic_, numeric_, n, 1, x.data(), &common_)) {
    return Status::failure("klu: solve failed (status " + std::to_string(common_.status) + ")");
  }
  return Status::success();
}

}  // namespace c2d
