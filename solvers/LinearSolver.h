#pragma once
// One interface over the sparse direct solvers (Eigen, SuiteSparse CHOLMOD,
// UMFPACK, KLU), chosen by name. Symbolic analysis once per sparsity pattern,
// numeric factorization per tangent, solves with the current factors.
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.h"

namespace c2d {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Symbolic analysis for A's pattern (A holds both triangles even when symmetric).
  // Called again only when the pattern changes (a new topology version).
  virtual Status analyze(const SparseMatrix& A, bool symmetric) = 0;
  // Numeric factorization of A, whose pattern is the analyzed one. A failure
  // (singular, or not positive definite for a Cholesky) is returned; the "auto"
  // solver falls back to an LU factorization by itself.
  virtual Status factorize(const SparseMatrix& A) = 0;
  // x = A^{-1} b with the current factors; x is sized by the caller.
  virtual Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
};

// Names: "auto" (default: CHOLMOD for symmetric, falling back to UMFPACK when the
// tangent is indefinite; UMFPACK for unsymmetric), "cholmod", "umfpack", "klu",
// "eigen-ldlt", "eigen-lu". Returns nullptr for an unknown name.
std::unique_ptr<LinearSolver> makeLinearSolver(std::string_view name);
std::vector<std::string> linearSolverNames();

}  // namespace c2d
