// The KLU solver (solvers/linear/KluSolver): a refactorization reuses the
// pivots, and a vanished pivot makes it pivot again.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "solvers/linear/KluSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::fromTriplets;
using test::Triplets;

TEST(LinearSolverKlu, RefactorReusesPivotsAndRepivotsWhenAPivotVanishes) {
  // [[4, 1], [1, 4]] is factored with diagonal pivots; [[0, 1], [1, 0]] has the
  // same pattern, but a zero diagonal pivot in either order: it needs a row swap.
  Triplets t{{0, 0, 4.0}, {1, 0, 1.0}, {0, 1, 1.0}, {1, 1, 4.0}};
  SparseMatrix A = fromTriplets(2, t);
  KluSolver s;
  ASSERT_TRUE(s.analyze(A, false));
  ASSERT_TRUE(s.factorize(A));
  EXPECT_FALSE(s.lastWasRefactor());
  A.coeffRef(0, 0) = 3.0;
  ASSERT_TRUE(s.factorize(A));
  EXPECT_TRUE(s.lastWasRefactor());
  A.coeffRef(0, 0) = 0.0;
  A.coeffRef(1, 1) = 0.0;
  const Status f = s.factorize(A);
  ASSERT_TRUE(f) << f.why;
  EXPECT_FALSE(s.lastWasRefactor());
  const Eigen::Vector2d b(1.0, 2.0);
  Eigen::VectorXd x(2);
  ASSERT_TRUE(s.solve(b, x));
  // [[0, 1], [1, 0]] x = (1, 2): x = (2, 1).
  EXPECT_NEAR(x(0), 2.0, 1e-15);
  EXPECT_NEAR(x(1), 1.0, 1e-15);
}

}  // namespace
}  // namespace c2d
