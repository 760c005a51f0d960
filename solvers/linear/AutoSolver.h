#pragma once
// The default solver. When the caller has grouped the equations by node (the
// analyses do), the block LU on the nodes' 3x3 blocks: it needs no pivoting
// for a frame's tangent, static or dynamic, factors in a third to a half of
// the time of KLU's refactorization, and keeps up with CHOLMOD's Cholesky on
// symmetric ones (the frame push takes the same time). Without a grouping,
// symmetric matrices go to CHOLMOD's Cholesky and unsymmetric ones to KLU. When the block LU finds it would need pivoting (a
// near-singular pivot block, growth of the entries: a tangent made indefinite
// by a softening hinge can do that) or the Cholesky finds the matrix not
// positive definite, the same matrix is factorized by KLU's pivoting LU
// instead, and KLU stays in use for every later factorization of this
// pattern: such a tangent usually stays so over the following iterations and
// steps, so retrying would mostly waste a failed factorization. The next
// analyze() (a new pattern) starts again. KLU rather than UMFPACK: frame
// tangents are very sparse, and KLU's refactorization reuses the pivot order
// and its storage.
#include <memory>

#include "solvers/linear/BlockLuSolver.h"
#include "solvers/linear/CholmodSolver.h"
#include "solvers/linear/LinearSolver.h"
#include "solvers/linear/KluSolver.h"

namespace c2d {

class AutoSolver final : public LinearSolver {
 public:
  AutoSolver();
  AutoSolver(const AutoSolver&) = delete;
  AutoSolver& operator=(const AutoSolver&) = delete;

  std::string name() const override { return "auto"; }
  void groupEquations(std::vector<int> group) override;
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  int singularEquation() const override;
  // The block LU's or the Cholesky's factors of A solved it too inaccurately
  // (an ill-conditioned tangent that needs pivoting between the nodes'
  // blocks): KLU factors it, and stays for the rest of the pattern, as when
  // the block LU meets a near-singular pivot block. KLU's own factors: a
  // fresh pivot search.
  bool refactorWithPivoting(const SparseMatrix& A) override;
  double conditionEstimate(const SparseMatrix& A) override;

  // "cholmod", "block-lu" or "klu": the solver the next factorize() will use.
  std::string activeName() const;
  // True once the Cholesky or the block LU has failed for the current pattern.
  bool fellBack() const { return analyzed_ && active_ != first(); }

 private:
  // KLU's factorization, with its symbolic analysis first if this
  // pattern has not had one yet.
  Status factorizeLu(const SparseMatrix& A);

  enum class Kind { Cholesky, BlockLu, Klu };
  // The solver a pattern starts with.
  Kind first() const;

  std::unique_ptr<CholmodSolver> cholesky_;
  std::unique_ptr<BlockLuSolver> blockLu_;
  std::unique_ptr<KluSolver> lu_;
  bool grouped_ = false;
  bool symmetric_ = false;
  bool luAnalyzed_ = false;
  Kind active_ = Kind::Klu;
  bool analyzed_ = false;
};

}  // namespace c2d
