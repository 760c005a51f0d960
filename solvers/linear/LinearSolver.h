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
#include "core/SparseMatrix.h"

namespace c2d {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Symbolic analysis for A's pattern (A holds both triangles even when symmetric).
  // Called again only when the pattern changes (a new topology version).
  virtual Status analyze(const SparseMatrix& A, bool symmetric) = 0;
  // The equations that belong together (group[i] for equation i: the dofs of
  // one node), for the solvers that factor dense blocks; the others ignore
  // it. Takes effect at the next analyze().
  virtual void groupEquations(std::vector<int> /*group*/) {}
  // Numeric factorization of A, whose pattern is the analyzed one. A failure
  // (singular, or not positive definite for a Cholesky) is returned; the "auto"
  // solver falls back to an LU factorization by itself.
  virtual Status factorize(const SparseMatrix& A) = 0;
  // x = A^{-1} b with the current factors; x is sized by the caller.
  virtual Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  // The equation (of A's numbering) whose pivot vanished when the last
  // factorize() failed for a singular matrix, or -1.
  virtual int singularEquation() const { return -1; }
  // When a solve with the factors of A missed K x = b (solvers/linear/CheckedSolve):
  // factors A again with partial pivoting where the last factorization did
  // not pivot, or reused an old pivot order. True when new factors are in
  // place; false when there is nothing better to try.
  virtual bool refactorWithPivoting(const SparseMatrix& /*A*/) { return false; }
  // An estimate of the 1-norm condition number of A from the current factors
  // of A, or -1 when the solver has none.
  virtual double conditionEstimate(const SparseMatrix& /*A*/) { return -1; }
};

// Names: "auto" (default: the block LU when the equations are grouped, else
// CHOLMOD for symmetric and KLU for unsymmetric matrices; KLU where the first
// one fails for want of pivoting), "cholmod", "umfpack", "klu", "block-lu",
// "eigen-ldlt", "eigen-lu". Returns nullptr for an unknown name.
std::unique_ptr<LinearSolver> makeLinearSolver(std::string_view name);
std::vector<std::string> linearSolverNames();

}  // namespace c2d
