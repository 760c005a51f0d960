#pragma once
// Sparse LU by KLU (BTF + AMD ordering, left-looking Gilbert-Peierls with
// partial pivoting), suited to the very sparse matrices of frames. The pivot
// order of the first factorization is reused by klu_refactor until it fails
// or loses accuracy; then a fresh pivoting factorization is made.
#include <klu.h>

#include "solvers/linear/DirectSolver.h"

namespace c2d {

class KluSolver final : public DirectSolver {
 public:
  KluSolver();
  ~KluSolver() override;

  std::string name() const override { return "klu"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  int singularEquation() const override { return singular_; }
  // A fresh pivot search when the factors reused an old pivot order.
  bool refactorWithPivoting(const SparseMatrix& A) override;
  double conditionEstimate(const SparseMatrix& A) override;

  // Whether the last successful factorize() reused the previous pivot order.
  bool lastWasRefactor() const { return lastWasRefactor_; }

 private:
  Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

  void freeSymbolic();
  void freeNumeric();
  Status freshFactor(int* p, int* i, double* x);

  klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  bool lastWasRefactor_ = false;
  int singular_ = -1;
};

}  // namespace c2d
