#pragma once
// Eigen's SimplicialLDLT (AMD ordering, no pivoting): A = P' L D L' P.
// Accepts indefinite matrices as long as no pivot is exactly zero; without
// pivoting such a factorization may be inaccurate, hence the LU alternatives.
#include <Eigen/SparseCholesky>

#include "solvers/linear/LinearSolver.h"
#include "solvers/SparsePattern.h"

namespace c2d {

class EigenLdltSolver final : public LinearSolver {
 public:
  EigenLdltSolver() = default;
  EigenLdltSolver(const EigenLdltSolver&) = delete;
  EigenLdltSolver& operator=(const EigenLdltSolver&) = delete;

  std::string name() const override { return "eigen-ldlt"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

 private:
  // Reads the lower triangle of the full (both triangles) matrix.
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt_;
  SparsePattern pattern_;
  bool factored_ = false;
};

}  // namespace c2d
