#include "solvers/linear/AutoSolver.h"

namespace c2d {

AutoSolver::AutoSolver()
    : cholesky_(std::make_unique<CholmodSolver>()),
      blockLu_(std::make_unique<BlockLuSolver>()),
      lu_(std::make_unique<KluSolver>()) {}

AutoSolver::Kind AutoSolver::first() const {
  if (grouped_) return Kind::BlockLu;
  return symmetric_ ? Kind::Cholesky : Kind::Klu;
}

std::string AutoSolver::activeName() const {
  switch (active_) {
    case Kind::Cholesky: return cholesky_->name();
    case Kind::BlockLu: return blockLu_->name();
    case Kind::Klu: break;
  }
  return lu_->name();
}

void AutoSolver::groupEquations(std::vector<int> group) {
  grouped_ = !group.empty();
  blockLu_->groupEquations(std::move(group));
}

Status AutoSolver::analyze(const SparseMatrix& A, bool symmetric) {
  analyzed_ = false;
  luAnalyzed_ = false;
  symmetric_ = symmetric;
  active_ = first();
  Status s = active_ == Kind::Cholesky ? cholesky_->analyze(A, true)
             : active_ == Kind::BlockLu ? blockLu_->analyze(A, symmetric)
                                        : lu_->analyze(A, symmetric);
  if (!s) return s;
  // KLU's analysis of a pattern the Cholesky or the block LU has waits until
  // they fail: most patterns never need it.
  luAnalyzed_ = active_ == Kind::Klu;
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
  if (active_ == Kind::Klu) return factorizeLu(A);
  const bool cholesky = active_ == Kind::Cholesky;
  const Status s = cholesky ? cholesky_->factorize(A) : blockLu_->factorize(A);
  // Bad input (pattern, NaN) would fail KLU too: only a Cholesky of an
  // indefinite matrix or a block LU that needs pivoting falls back.
  if (s || !(cholesky ? cholesky_->notPositiveDefinite() : blockLu_->notStable())) return s;
  active_ = Kind::Klu;
  if (Status t = factorizeLu(A); !t) return Status::failure(s.why + "; " + t.why);
  return Status::success();
}

bool AutoSolver::refactorWithPivoting(const SparseMatrix& A) {
  if (!analyzed_) return false;
  if (active_ == Kind::Klu) return lu_->refactorWithPivoting(A);
  active_ = Kind::Klu;
  return static_cast<bool>(factorizeLu(A));
}

double AutoSolver::conditionEstimate(const SparseMatrix& A) {
  return analyzed_ && active_ == Kind::Klu ? lu_->conditionEstimate(A) : -1.0;
}

int AutoSolver::singularEquation() const {
  return active_ == Kind::Klu       ? lu_->singularEquation()
         : active_ == Kind::BlockLu ? blockLu_->singularEquation()
                                    : -1;
}

Status AutoSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!analyzed_) return Status::failure("auto: solve() before analyze()");
  switch (active_) {
    case Kind::Cholesky: return cholesky_->solve(b, x);
    case Kind::BlockLu: return blockLu_->solve(b, x);
    case Kind::Klu: break;
  }
  return lu_->solve(b, x);
}

}  // namespace c2d
