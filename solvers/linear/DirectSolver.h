#pragma once
// What the sparse direct solvers share around their own factorization: the
// pattern recorded at analyze() and checked at every factorize(), and the
// checks of a solve (factors in place, vectors of the matrix size, a finite
// right-hand side and a finite solution). Every failure is named after the
// solver ("klu: ...").
#include <string>

#include "solvers/SparsePattern.h"
#include "solvers/linear/LinearSolver.h"

namespace c2d {

class DirectSolver : public LinearSolver {
 public:
  DirectSolver() = default;
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  // Checks b and x, solves with solveFactored() and checks x.
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) final;

 protected:
  // x = A^{-1} b with the current factors; b is finite and b, x are of the
  // matrix size.
  virtual Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;

  // "name: why" as a failure.
  Status failure(const std::string& why) const;
  // pattern_.record(A) and pattern_.check(A), their failures named.
  Status recordPattern(const SparseMatrix& A);
  Status checkPattern(const SparseMatrix& A) const;

  SparsePattern pattern_;
  bool factored_ = false;
};

}  // namespace c2d
