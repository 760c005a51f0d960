#pragma once
// The sparsity pattern a solver was analyzed for, kept so that every numeric
// factorization can check cheaply (O(nnz), no allocation) that it is handed the
// same pattern and finite values, and so that solvers which need the matrix
// again at solve time (UMFPACK's iterative refinement) own a stable copy.
#include <string>
#include <vector>

#include "core/Error.h"
#include "solvers/linear/LinearSolver.h"

namespace c2d {

class SparsePattern {
 public:
  // Records A's pattern. Fails (and records nothing) when A is not square, not
  // compressed, or has row indices out of range.
  Status record(const SparseMatrix& A);
  void clear();

  bool empty() const { return outer_.empty(); }
  int size() const { return n_; }
  int nonZeros() const { return static_cast<int>(inner_.size()); }
  // True when the row indices increase strictly within every column (UMFPACK needs it).
  bool sorted() const { return sorted_; }

  // Success when A has exactly the recorded pattern and only finite values;
  // otherwise a failure naming the first offending column or entry.
  Status check(const SparseMatrix& A) const;

  // The recorded pattern, in compressed-column form (size n+1 and nnz). Non-const
  // pointers because the C libraries declare their read-only inputs without const.
  int* outer() { return outer_.data(); }
  int* inner() { return inner_.data(); }

 private:
  int n_ = 0;
  bool sorted_ = true;
  std::vector<int> outer_;
  std::vector<int> inner_;
};

// "non-finite entry (row 3, column 7)" or an empty string when every value is finite.
std::string findNonFinite(const SparseMatrix& A);

}  // namespace c2d
