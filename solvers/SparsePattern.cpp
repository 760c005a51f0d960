#include "solvers/SparsePattern.h"

#include <algorithm>
#include <cmath>

namespace c2d {

namespace {
bool finiteValues(const SparseMatrix& A) {
  return Eigen::Map<const Eigen::VectorXd>(A.valuePtr(), A.nonZeros()).allFinite();
}
}  // namespace

std::string findNonFinite(const SparseMatrix& A) {
  if (finiteValues(A)) return {};
  for (int j = 0; j < A.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (!std::isfinite(it.value())) {
        return "non-finite entry " + std::to_string(it.value()) + " at (row " +
               std::to_string(it.row()) + ", column " + std::to_string(it.col()) + ")";
      }
    }
  }
  return "non-finite entry";
}

Status SparsePattern::record(const SparseMatrix& A) {
  clear();
  if (A.rows() != A.cols()) {
    return Status::failure("matrix is not square (" + std::to_string(A.rows()) + " x " +
                           std::to_string(A.cols()) + ")");
  }
  if (!A.isCompressed()) return Status::failure("matrix is not in compressed form");
  const int n = static_cast<int>(A.cols());
  const int nnz = static_cast<int>(A.nonZeros());
  const int* p = A.outerIndexPtr();
  const int* i = A.innerIndexPtr();
  bool sorted = true;
  for (int j = 0; j < n; ++j) {
    for (int k = p[j]; k < p[j + 1]; ++k) {
      if (i[k] < 0 || i[k] >= n) {
        return Status::failure("row index " + std::to_string(i[k]) + " out of range in column " +
                               std::to_string(j));
      }
      if (k > p[j] && i[k] <= i[k - 1]) sorted = false;
    }
  }
  n_ = n;
  sorted_ = sorted;
  outer_.assign(p, p + n + 1);
  inner_.assign(i, i + nnz);
  return Status::success();
}

void SparsePattern::clear() {
  n_ = 0;
  sorted_ = true;
  outer_.clear();
  inner_.clear();
}

Status SparsePattern::check(const SparseMatrix& A) const {
  if (empty()) return Status::failure("no symbolic analysis: call analyze() first");
  if (A.rows() != n_ || A.cols() != n_) {
    return Status::failure("matrix is " + std::to_string(A.rows()) + " x " +
                           std::to_string(A.cols()) + " but the analysis was for " +
                           std::to_string(n_) + " x " + std::to_string(n_));
  }
  if (!A.isCompressed()) return Status::failure("matrix is not in compressed form");
  if (A.nonZeros() != nonZeros() || !std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) ||
      !std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr())) {
    return Status::failure("sparsity pattern differs from the analyzed one (analyze() again)");
  }
  if (!finiteValues(A)) return Status::failure(findNonFinite(A));
  return Status::success();
}

}  // namespace c2d
