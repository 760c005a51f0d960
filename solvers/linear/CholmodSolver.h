#pragma once
// Sparse Cholesky A = L L' by CHOLMOD (supernodal or simplicial, as CHOLMOD
// chooses; fill-reducing ordering AMD, or METIS when CHOLMOD finds it better).
// Only for symmetric matrices; a matrix that is not positive definite is a
// failure, which AutoSolver turns into an LU fallback.
#include <cholmod.h>

#include "solvers/linear/DirectSolver.h"

namespace c2d {

class CholmodSolver final : public DirectSolver {
 public:
  // Automatic lets CHOLMOD choose from the flop count per nonzero of L (the
  // very sparse frame matrices usually get the simplicial method).
  enum class Method { Automatic, Simplicial, Supernodal };

  explicit CholmodSolver(Method method = Method::Automatic);
  ~CholmodSolver() override;

  std::string name() const override { return "cholmod"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;

  // True when the last factorize() failed because A is not positive definite
  // (indefinite or singular), as opposed to bad input or lack of memory.
  bool notPositiveDefinite() const { return notPosDef_; }
  // Whether the current factor is supernodal (meaningful after analyze()).
  bool supernodal() const { return factor_ && factor_->is_super; }

 private:
  Status solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

  // Points the header view_ at A's arrays (no copy). CHOLMOD only reads them.
  void bindView(const SparseMatrix& A);
  void freeFactor();
  std::string commonError(const char* what) const;

  cholmod_common common_{};
  cholmod_sparse view_{};  // header over the caller's matrix memory, never allocated
  cholmod_dense rhs_{};    // header over the caller's right-hand side
  cholmod_factor* factor_ = nullptr;
  // Solution and workspace owned by CHOLMOD, allocated on the first solve and
  // reused by cholmod_solve2 for every later one.
  cholmod_dense* sol_ = nullptr;
  cholmod_dense* work1_ = nullptr;
  cholmod_dense* work2_ = nullptr;
  bool notPosDef_ = false;
};

}  // namespace c2d
