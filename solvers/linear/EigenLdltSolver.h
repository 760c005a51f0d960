#pragma once
// Eigen's SimplicialLDLT (AMD ordering, no pivoting): A = P' L D L' P.
// Accepts indefinite matrices as long as no pivot is exactly zero; without
// pivoting such a factorization may be inaccurate, hence the LU alternatives.
#include <Eigen/SparseCholesky>

#include "solvers/linear/EigenDirectSolver.h"

namespace c2d {

// Reads the lower triangle of the full (both triangles) matrix.
class EigenLdltSolver final
    : public EigenDirectSolver<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>> {
 public:
  std::string name() const override { return "eigen-ldlt"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;

 private:
  std::string singular() const override { return "matrix is singular (zero pivot in D)"; }
};

}  // namespace c2d
