#pragma once
// Sparse LU with partial pivoting by UMFPACK (multifrontal). Handles
// unsymmetric and symmetric indefinite matrices; with symmetric = true the
// symmetric strategy (AMD on A + A', diagonal pivots preferred) is used.
#include <vector>

#include "solvers/linear/LinearSolver.h"
#include "solvers/SparsePattern.h"

namespace c2d {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  std::string name() const override { return "umfpack"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

 private:
  void freeSymbolic();
  void freeNumeric();

  std::vector<double> control_;
  std::vector<double> info_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  // Iterative refinement in solve() needs the factorized matrix: a copy of the
  // pattern and of the values of the last factorize(), so that the caller may
  // overwrite its matrix (the next tangent) while these factors are still used.
  SparsePattern pattern_;
  std::vector<double> values_;
  std::vector<double> rhsCopy_;  // for solve(b, b)
  std::vector<int> intWork_;     // umfpack_di_wsolve workspace, sized in analyze()
  std::vector<double> work_;
  bool factored_ = false;
};

}  // namespace c2d
