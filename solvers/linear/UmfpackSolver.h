#pragma once
// Sparse LU with partial pivoting by UMFPACK (multifrontal). Handles
// unsymmetric and symmetric indefinite matrices; with symmetric = true the
// symmetric strategy (AMD on A + A', diagonal pivots preferred) is used.
#include <vector>

#include "solvers/linear/DirectSolver.h"

namespace c2d {

class UmfpackSolver final : public DirectSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;

  std::string name() const override { return "umfpack"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;

 private:
  Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

  void freeSymbolic();
  void freeNumeric();

  std::vector<double> control_;
  std::vector<double> info_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  // Iterative refinement in solve() needs the factorized matrix: the recorded
  // pattern and a copy of the values of the last factorize(), so that the caller
  // may overwrite its matrix (the next tangent) while these factors are still used.
  std::vector<double> values_;
  std::vector<double> rhsCopy_;  // for solve(b, b)
  std::vector<int> intWork_;     // umfpack_di_wsolve workspace, sized in analyze()
  std::vector<double> work_;
};

}  // namespace c2d
