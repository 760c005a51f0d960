#pragma once
// Eigen's SparseLU (COLAMD column ordering, supernodal, partial pivoting):
// the dependency-free LU for unsymmetric or indefinite matrices.
#include <Eigen/SparseLU>

#include "solvers/linear/EigenDirectSolver.h"

namespace c2d {

class EigenLuSolver final
    : public EigenDirectSolver<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>> {
 public:
  std::string name() const override { return "eigen-lu"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;

 private:
  std::string singular() const override {
    return "matrix is singular (" + decomposition_.lastErrorMessage() + ")";
  }
};

}  // namespace c2d
