#include "solvers/AutoSolver.h"

namespace c2d {

AutoSolver::AutoSolver()
    : cholesky_(std::make_unique<CholmodSolver>()), lu_(std::make_unique<KluSolver>()) {}

std::string AutoSolver::activeName() const {
  return (symmetric_ && !fellBack_) ? cholesky_->name() : lu_->name();
}

Status AutoSolver::analyze(const SparseMatrix& A, bool symmetric) {
  analyzed_ = false;
  luAnalyzed_ = false;
  fellBack_ = false;
  symmetric_ = symmetric;
  Status s = symmetric ? cholesky_->analyze(A, true) : lu_->analyze(A, false);
  if (!s) return s;
  // The LU analysis of a symmetric pattern waits until a Cholesky fails:
  // most patterns never need it.
  luAnalyzed_ = !symmetric;
  analyzed_ = true;
  return Status::success();
}

Status AutoSolver::factorizeLu(const SparseMatrix& A) {
  if (!luAnalyzed_) {
    if (Status s = lu_->analyze(A, symmetric_); !s) return s;
    luAnalyzed_ = true;
  }
  return lu_->factorize(A);
}

Status AutoSolver::factorize(const SparseMatrix& A) {
  if (!analyzed_) return Status::failure("auto: factorize() before analyze()");
  if (symmetric_ && !fellBack_) {
    const Status s = cholesky_->factorize(A);
    // Bad input (pattern, NaN) would fail the LU too: only a failed Cholesky falls back.
    if (s || !cholesky_->notPositiveDefinite()) return s;
    fellBack_ = true;
    if (Status t = factorizeLu(A); !t) return Status::failure(s.why + "; " + t.why);
    return Status::success();
  }
  return factorizeLu(A);
}

Status AutoSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!analyzed_) return Status::failure("auto: solve() before analyze()");
  return (symmetric_ && !fellBack_) ? cholesky_->solve(b, x) : lu_->solve(b, x);
}

}  // namespace c2d
