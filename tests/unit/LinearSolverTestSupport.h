#pragma once
// Shared by the linear solver tests: matrices from triplets, random SPD graph
// Laplacians (chains and grids), random vectors, the dense LU solution and the
// relative residual.
#include <Eigen/Dense>
#include <random>
#include <vector>

#include "solvers/linear/LinearSolver.h"

namespace c2d::test {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

// The n x n compressed matrix of the triplets.
inline SparseMatrix fromTriplets(int n, const Triplets& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// An edge of weight w of a graph Laplacian.
inline void addEdge(Triplets& t, int i, int j, double w) {
  t.emplace_back(i, i, w);
  t.emplace_back(j, j, w);
  t.emplace_back(i, j, -w);
  t.emplace_back(j, i, -w);
}

// Weighted graph Laplacians plus a positive diagonal, symmetric positive
// definite for any positive weights, with the pattern of the graph: a chain of
// n nodes and an nx x ny grid, random weights.
inline SparseMatrix laplacian1d(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0.5, 2.0);
  Triplets t;
  for (int i = 0; i + 1 < n; ++i) addEdge(t, i, i + 1, w(rng));
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, 0.01 * w(rng));
  return fromTriplets(n, t);
}

inline SparseMatrix laplacian2d(int nx, int ny, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0.5, 2.0);
  Triplets t;
  auto id = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx) addEdge(t, id(i, j), id(i + 1, j), w(rng));
      if (j + 1 < ny) addEdge(t, id(i, j), id(i, j + 1), w(rng));
      t.emplace_back(id(i, j), id(i, j), 0.01 * w(rng));
    }
  }
  return fromTriplets(nx * ny, t);
}

// Entries uniform in [-1, 1].
inline Eigen::VectorXd randomVector(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = u(rng);
  return v;
}

// The dense LU solution and the relative residual of x.
inline Eigen::VectorXd denseSolve(const SparseMatrix& A, const Eigen::VectorXd& b) {
  return Eigen::MatrixXd(A).fullPivLu().solve(b);
}

inline double relResidual(const SparseMatrix& A, const Eigen::VectorXd& x,
                          const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
}

}  // namespace c2d::test
