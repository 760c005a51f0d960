// The block LU solver (solvers/linear/BlockLuSolver) on frame-like matrices of
// node blocks against dense solutions: new values on the same pattern, zero
// blocks changing from one factorization to the next, pivots within a block
// and large groups split.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <vector>

#include "solvers/linear/BlockLuSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::denseSolve;
using test::fromTriplets;
using test::randomVector;
using test::relResidual;
using test::Triplets;

// A frame-like matrix: nodes of three equations (two at the supports, one at
// a slave's rotation) on a grid, every pair of neighbours coupled by a dense,
// unsymmetric 3x3 block, with a dominant diagonal block as a dynamic tangent's.
// The equations of a node are scattered over the numbering.
struct NodeMatrix {
  SparseMatrix A;
  std::vector<int> group;
};

NodeMatrix nodeMatrix(int nx, int ny, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int nodes = nx * ny;
  std::vector<std::vector<int>> eqs(nodes);
  int n = 0;
  for (int a = 0; a < nodes; ++a) {
    const int k = a % 7 == 0 ? 2 : a % 11 == 0 ? 1 : 3;
    for (int d = 0; d < k; ++d) eqs[a].push_back(n++);
  }
  std::vector<int> renumber(n);
  for (int i = 0; i < n; ++i) renumber[i] = i;
  std::shuffle(renumber.begin(), renumber.end(), rng);
  NodeMatrix m;
  m.group.assign(n, -1);
  for (int a = 0; a < nodes; ++a)
    for (int& e : eqs[a]) {
      e = renumber[e];
      m.group[e] = a;
    }
  Triplets t;
  auto couple = [&](int a, int b, double scale) {
    for (int i : eqs[a])
      for (int j : eqs[b]) t.emplace_back(i, j, scale * u(rng));
  };
  for (int a = 0; a < nodes; ++a) {
    couple(a, a, 1.0);
    for (int i : eqs[a]) t.emplace_back(i, i, 40.0);
    const int x = a % nx, y = a / nx;
    if (x + 1 < nx) couple(a, a + 1, 5.0), couple(a + 1, a, 5.0);
    if (y + 1 < ny) couple(a, a + nx, 5.0), couple(a + nx, a, 5.0);
  }
  m.A = fromTriplets(n, t);
  return m;
}

TEST(LinearSolverBlockLu, NodeBlocksMatchDense) {
  std::mt19937 rng(24);
  for (int k = 0; k < 3; ++k) {
    NodeMatrix m = nodeMatrix(6 + 3 * k, 5 + k, rng);
    const int n = static_cast<int>(m.A.rows());
    BlockLuSolver s;
    s.groupEquations(m.group);
    ASSERT_TRUE(s.analyze(m.A, false));
    EXPECT_EQ(s.numBlocks(), (6 + 3 * k) * (5 + k));
    for (int round = 0; round < 2; ++round) {
      const Status f = s.factorize(m.A);
      ASSERT_TRUE(f) << f.why;
      const Eigen::VectorXd b = randomVector(n, rng);
      Eigen::VectorXd x(n);
      ASSERT_TRUE(s.solve(b, x));
      EXPECT_LT((x - denseSolve(m.A, b)).norm(), 1e-12 * x.norm());
      EXPECT_LT(relResidual(m.A, x, b), 1e-14);
      // New values on the same pattern.
      for (int j = 0; j < n; ++j)
        for (SparseMatrix::InnerIterator it(m.A, j); it; ++it) it.valueRef() *= 1.0 + 0.1 * j / n;
    }
  }
}

TEST(LinearSolverBlockLu, ZeroBlocksOfThePatternChangeFromOneFactorizationToTheNext) {
  // The pattern keeps couplings whose values are zero (pairs of members that
  // do not touch): the factorization passes over the zero blocks of L and U.
  // Each factorization of the same pattern zeroes another third of the
  // couplings between nodes and gives the others back their values: the
  // solution matches the dense one every time.
  std::mt19937 rng(31);
  NodeMatrix m = nodeMatrix(9, 7, rng);
  const SparseMatrix full = m.A;
  const int n = static_cast<int>(m.A.rows());
  BlockLuSolver s;
  s.groupEquations(m.group);
  ASSERT_TRUE(s.analyze(m.A, false));
  for (int round = 0; round < 3; ++round) {
    int zeroed = 0;
    for (int j = 0; j < n; ++j) {
      SparseMatrix::InnerIterator source(full, j);
      for (SparseMatrix::InnerIterator it(m.A, j); it; ++it, ++source) {
        const int a = m.group[it.row()], b = m.group[j];
        const bool zero = a != b && (a + b + round) % 3 == 0;
        it.valueRef() = zero ? 0.0 : source.value();
        zeroed += zero;
      }
    }
    ASSERT_GT(zeroed, 0);
    const Status f = s.factorize(m.A);
    ASSERT_TRUE(f) << f.why;
    const Eigen::VectorXd b = randomVector(n, rng);
    Eigen::VectorXd x(n);
    ASSERT_TRUE(s.solve(b, x));
    EXPECT_LT((x - denseSolve(m.A, b)).norm(), 1e-12 * x.norm()) << "round " << round;
  }
}

TEST(LinearSolverBlockLu, PivotsWithinABlockAndSplitsLargeGroups) {
  // A node block with zero diagonal entries, [[0, 1, 0], [1, 0, 0], [0, 0, 1]]
  // scaled, coupled to a second node: the inverse of the block needs no
  // pivot among its entries. Then the same matrix as one group of six
  // equations: split into blocks of three.
  Triplets t;
  const double blk[3][3] = {{0, 2, 0}, {3, 0, 0}, {0, 0, 4}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (blk[i][j] != 0) t.emplace_back(i, j, blk[i][j]), t.emplace_back(i + 3, j + 3, blk[i][j] + 1);
      t.emplace_back(i, j + 3, 0.1 * (i + 2 * j + 1));
      t.emplace_back(i + 3, j, -0.2 * (2 * i + j + 1));
    }
  const SparseMatrix A = fromTriplets(6, t);
  const Eigen::VectorXd b = (Eigen::VectorXd(6) << 1, -2, 3, 0.5, 4, -1).finished();
  for (const std::vector<int>& group :
       {std::vector<int>{0, 0, 0, 1, 1, 1}, std::vector<int>{5, 5, 5, 5, 5, 5}}) {
    BlockLuSolver s;
    s.groupEquations(group);
    ASSERT_TRUE(s.analyze(A, false));
    EXPECT_EQ(s.numBlocks(), 2);
    ASSERT_TRUE(s.factorize(A));
    Eigen::VectorXd x(6);
    ASSERT_TRUE(s.solve(b, x));
    EXPECT_LT((x - denseSolve(A, b)).norm(), 1e-14 * x.norm());
  }
}

}  // namespace
}  // namespace c2d
