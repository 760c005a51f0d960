#include "solvers/linear/CholmodSolver.h"

#include <algorithm>
#include <string>

namespace c2d {

CholmodSolver::CholmodSolver(Method method) {
  cholmod_start(&common_);
  switch (method) {
    case Method::Automatic:
      common_.supernodal = CHOLMOD_AUTO;
      break;
    case Method::Simplicial:
      common_.supernodal = CHOLMOD_SIMPLICIAL;
      break;
    case Method::Supernodal:
      common_.supernodal = CHOLMOD_SUPERNODAL;
      break;
  }
  // Failures come back as Status; CHOLMOD's own messages on stderr would only
  // duplicate them (a softening tangent fails the Cholesky routinely).
  common_.print = 0;
  // Keep a true L L' even when CHOLMOD picks the simplicial method: its
  // default there is an unpivoted L D L', which "succeeds" on an indefinite
  // tangent with no stability guarantee. L L' stops at the first non-positive
  // pivot instead, so indefiniteness is detected and the caller can switch to
  // a pivoting LU.
  common_.final_ll = 1;
  // The equations come numbered in a fill-reducing order (core/DofMap), so the
  // natural ordering keeps the fill low and spares a permuted copy of the
  // matrix at every factorization.
  // (A forced supernodal factorization keeps CHOLMOD's own orderings: it needs
  // the elimination-tree postordering anyway.)
  if (method != Method::Supernodal) {
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_NATURAL;
    common_.postorder = 0;
  }
}

CholmodSolver::~CholmodSolver() {
  freeFactor();
  cholmod_free_dense(&sol_, &common_);
  cholmod_free_dense(&work1_, &common_);
  cholmod_free_dense(&work2_, &common_);
  cholmod_finish(&common_);
}

void CholmodSolver::freeFactor() {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  factor_ = nullptr;
  factored_ = false;
}

void CholmodSolver::bindView(const SparseMatrix& A) {
  view_.nrow = static_cast<size_t>(A.rows());
  view_.ncol = static_cast<size_t>(A.cols());
  view_.nzmax = static_cast<size_t>(A.nonZeros());
  // CHOLMOD takes non-const pointers but does not write to its input matrix.
  view_.p = const_cast<int*>(A.outerIndexPtr());
  view_.i = const_cast<int*>(A.innerIndexPtr());
  view_.nz = nullptr;
  view_.x = const_cast<double*>(A.valuePtr());
  view_.z = nullptr;
  // Both triangles are stored; stype = 1 makes CHOLMOD read the upper one only.
  view_.stype = 1;
  view_.itype = CHOLMOD_INT;
  view_.xtype = CHOLMOD_REAL;
  view_.dtype = CHOLMOD_DOUBLE;
  view_.sorted = pattern_.sorted() ? 1 : 0;
  view_.packed = 1;
}

std::string CholmodSolver::commonError(const char* what) const {
  std::string s = std::string("cholmod: ") + what + " failed";
  switch (common_.status) {
    case CHOLMOD_OUT_OF_MEMORY:
      return s + " (out of memory)";
    case CHOLMOD_TOO_LARGE:
      return s + " (problem too large)";
    case CHOLMOD_INVALID:
      return s + " (invalid input)";
    default:
      return s + " (status " + std::to_string(common_.status) + ")";
  }
}

Status CholmodSolver::analyze(const SparseMatrix& A, bool symmetric) {
  freeFactor();
  notPosDef_ = false;
  if (!symmetric)
    return Status::failure("cholmod: a Cholesky factorization needs a symmetric matrix");
  if (Status s = recordPattern(A); !s) return s;
  bindView(A);
  factor_ = cholmod_analyze(&view_, &common_);
  if (!factor_ || common_.status < CHOLMOD_OK) {
    freeFactor();
    pattern_.clear();
    return Status::failure(commonError("symbolic analysis"));
  }
  return Status::success();
}

Status CholmodSolver::factorize(const SparseMatrix& A) {
  factored_ = false;
  notPosDef_ = false;
  if (!factor_) return Status::failure("cholmod: factorize() before analyze()");
  if (Status s = checkPattern(A); !s) return s;
  bindView(A);
  // Numeric factorization into the existing factor: the symbolic analysis and
  // CHOLMOD's workspace in common_ are reused.
  const int ok = cholmod_factorize(&view_, factor_, &common_);
  if (common_.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n) {
    notPosDef_ = true;
    // Name the row/column of A (not of the permuted matrix) whose pivot failed:
    // it points at the dof that lost its stiffness.
    const size_t k = factor_->minor;
    const int* perm = static_cast<const int*>(factor_->Perm);
    const size_t dof = (perm && k < factor_->n) ? static_cast<size_t>(perm[k]) : k;
    return Status::failure("cholmod: matrix not positive definite (non-positive pivot at row " +
                           std::to_string(dof) + " of " + std::to_string(factor_->n) +
                           ", elimination step " + std::to_string(k) + ")");
  }
  if (!ok || common_.status < CHOLMOD_OK) return Status::failure(commonError("factorization"));
  factored_ = true;
  return Status::success();
}

Status CholmodSolver::solveFactored(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const int n = pattern_.size();
  rhs_.nrow = static_cast<size_t>(n);
  rhs_.ncol = 1;
  rhs_.nzmax = static_cast<size_t>(n);
  rhs_.d = static_cast<size_t>(n);
  rhs_.x = const_cast<double*>(b.data());  // read only by cholmod_solve2
  rhs_.z = nullptr;
  rhs_.xtype = CHOLMOD_REAL;
  rhs_.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs_, nullptr, &sol_, nullptr, &work1_, &work2_,
                      &common_)) {
    return Status::failure(commonError("solve"));
  }
  const double* s = static_cast<const double*>(sol_->x);
  std::copy(s, s + n, x.data());
  return Status::success();
}

}  // namespace c2d
