#pragma once
// The sparse matrix of the assembled tangent (Eigen, column-major, int
// indices): what the assembler builds and the linear solvers factor.
#include <Eigen/Sparse>

namespace c2d {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace c2d
