#pragma once
// The default solver. Symmetric matrices go to CHOLMOD's Cholesky; when it
// finds the matrix not positive definite (a softening hinge has made the
// tangent indefinite), the same matrix is factorized by KLU's pivoting LU
// instead, and KLU stays in use for every later factorization of this
// pattern: an indefinite tangent usually stays indefinite over the following
// iterations and steps, so retrying the Cholesky each time would mostly waste a
// failed factorization. The next analyze() (a new pattern) starts again with
// CHOLMOD. Unsymmetric matrices go to KLU directly. KLU rather than UMFPACK:
// frame tangents are very sparse, and KLU's refactorization reuses the pivot
// order and its storage, which halved the time of the six-story collapse
// workflow (mid-point tangents are unsymmetric).
#include <memory>

#include "solvers/CholmodSolver.h"
#include "solvers/LinearSolver.h"
#include "solvers/KluSolver.h"

namespace c2d {

class AutoSolver final : public LinearSolver {
 public:
  AutoSolver();
  AutoSolver(const AutoSolver&) = delete;
  AutoSolver& operator=(const AutoSolver&) = delete;

  std::string name() const override { return "auto"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override;
  Status factorize(const SparseMatrix& A) override;
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;

  // "cholmod" or "klu": the solver the next factorize() will use.
  std::string activeName() const;
  // True once the Cholesky has failed for the current pattern.
  bool fellBack() const { return fellBack_; }

 private:
  // KLU's factorization, with its symbolic analysis first if this
  // pattern has not had one yet.
  Status factorizeLu(const SparseMatrix& A);

  std::unique_ptr<CholmodSolver> cholesky_;
  std::unique_ptr<KluSolver> lu_;
  bool symmetric_ = false;
  bool luAnalyzed_ = false;
  bool fellBack_ = false;
  bool analyzed_ = false;
};

}  // namespace c2d
