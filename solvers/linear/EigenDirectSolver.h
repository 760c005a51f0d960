#pragma once
// What Eigen's sparse direct solvers share behind the one interface: the
// numeric factorization of the analyzed pattern and the solve with its
// factors. Decomposition is an Eigen sparse solver (SimplicialLDLT, SparseLU);
// the solver names the cause of a failed factorization.
#include <Eigen/Core>
#include <string>

#include "solvers/linear/DirectSolver.h"

namespace c2d {

template <class Decomposition>
class EigenDirectSolver : public DirectSolver {
 public:
  Status factorize(const SparseMatrix& A) override {
    factored_ = false;
    if (Status s = checkPattern(A); !s) return s;
    decomposition_.factorize(A);
    if (decomposition_.info() != Eigen::Success) return failure(singular());
    factored_ = true;
    return Status::success();
  }

 protected:
  // Why the last factorize() failed: "matrix is singular (...)".
  virtual std::string singular() const = 0;

  Decomposition decomposition_;

 private:
  Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = decomposition_.solve(b);
    return Status::success();
  }
};

}  // namespace c2d
