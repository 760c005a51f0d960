#pragma once
// Eigen's SparseLU (COLAMD column ordering, supernodal, partial pivoting):
// the dependency-free LU for unsymmetric or indefinite matrices.
#include <Eigen/SparseLU>

#include "solvers/linear/LinearSolver.h"
#include "solvers/SparsePattern.h"

namespace c2d {

class EigenLuSolver final : public LinearSolver {
 public:
  EigenLuSolver() = default;
  EigenLuSolver(const EigenLuSolver&) = delete;
  EigenLuSolver& operator=(const EigenLuSolver&) = delete;

  std::string name() const override { return "eigen-lu"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

 private:
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  SparsePattern pattern_;
  bool factored_ = false;
};

}  // namespace c2d
