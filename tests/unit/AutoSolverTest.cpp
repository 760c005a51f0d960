// The automatic linear solver (solvers/linear/AutoSolver): the Cholesky
// falling back to an LU and staying there until the next analysis, bad input
// not falling back, unsymmetric tangents to the block LU when grouped (else
// KLU), the block LU falling back to KLU where it needs pivoting, and a
// singular tangent failing in both.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <random>
#include <string>

#include "solvers/linear/AutoSolver.h"
#include "solvers/linear/BlockLuSolver.h"
#include "solvers/linear/LinearSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::fromTriplets;
using test::laplacian1d;
using test::laplacian2d;
using test::randomVector;
using test::relResidual;
using test::Triplets;

TEST(LinearSolverAuto, FallsBackToLuAndStaysThereUntilAnalyze) {
  std::mt19937 rng(20);
  const SparseMatrix spd = laplacian2d(8, 7, rng);
  SparseMatrix indefinite = spd;
  for (int j = 0; j < indefinite.outerSize(); ++j) indefinite.coeffRef(j, j) -= 1.0;
  {
    auto cholesky = makeLinearSolver("cholmod");
    ASSERT_TRUE(cholesky->analyze(spd, true));
    ASSERT_FALSE(cholesky->factorize(indefinite));  // the premise of the fallback
  }

  AutoSolver s;
  ASSERT_TRUE(s.analyze(spd, true));
  EXPECT_EQ(s.activeName(), "cholmod");
  ASSERT_TRUE(s.factorize(spd));
  EXPECT_FALSE(s.fellBack());

  const Eigen::VectorXd b = randomVector(56, rng);
  Eigen::VectorXd x(56);
  const Status f = s.factorize(indefinite);
  ASSERT_TRUE(f) << f.why;
  EXPECT_TRUE(s.fellBack());
  EXPECT_EQ(s.activeName(), "klu");
  ASSERT_TRUE(s.solve(b, x));
  EXPECT_LT(relResidual(indefinite, x, b), 1e-12);

  // An SPD tangent on the same pattern stays with the LU.
  ASSERT_TRUE(s.factorize(spd));
  EXPECT_EQ(s.activeName(), "klu");
  ASSERT_TRUE(s.solve(b, x));
  EXPECT_LT(relResidual(spd, x, b), 1e-12);

  // A new analysis starts over with the Cholesky.
  ASSERT_TRUE(s.analyze(spd, true));
  EXPECT_EQ(s.activeName(), "cholmod");
  EXPECT_FALSE(s.fellBack());
  ASSERT_TRUE(s.factorize(spd));
  ASSERT_TRUE(s.solve(b, x));
  EXPECT_LT(relResidual(spd, x, b), 1e-12);
}

TEST(LinearSolverAuto, BadInputDoesNotFallBack) {
  std::mt19937 rng(23);
  SparseMatrix A = laplacian1d(12, rng);
  AutoSolver s;
  ASSERT_TRUE(s.analyze(A, true));
  A.coeffRef(3, 3) = std::numeric_limits<double>::infinity();
  const Status f = s.factorize(A);
  EXPECT_FALSE(f);
  EXPECT_NE(f.why.find("non-finite"), std::string::npos) << f.why;
  EXPECT_FALSE(s.fellBack());
  EXPECT_EQ(s.activeName(), "cholmod");
}

TEST(LinearSolverAuto, UnsymmetricGoesToBlockLuWhenGroupedOtherwiseToKlu) {
  Triplets t{{0, 0, 2.0}, {1, 0, 1.0}, {0, 1, 3.0}, {1, 1, 4.0}};
  const SparseMatrix A = fromTriplets(2, t);
  for (const bool grouped : {false, true}) {
    AutoSolver s;
    if (grouped) s.groupEquations({0, 0});
    ASSERT_TRUE(s.analyze(A, false));
    EXPECT_EQ(s.activeName(), grouped ? "block-lu" : "klu");
    ASSERT_TRUE(s.factorize(A));
    Eigen::VectorXd x(2);
    ASSERT_TRUE(s.solve(Eigen::Vector2d(5.0, 5.0), x));
    // [[2, 3], [1, 4]] x = (5, 5): x = (1, 1).
    EXPECT_NEAR(x(0), 1.0, 1e-15);
    EXPECT_NEAR(x(1), 1.0, 1e-15);
  }
}

TEST(LinearSolverAuto, BlockLuFallsBackToKluWhereItNeedsPivoting) {
  // [[1e-13, 1], [1, 1]], each equation its own block: without pivoting the
  // factors grow by 1e13 over the matrix; KLU swaps the rows.
  Triplets t{{0, 0, 1e-13}, {1, 0, 1.0}, {0, 1, 1.0}, {1, 1, 1.0}};
  SparseMatrix A = fromTriplets(2, t);
  AutoSolver s;
  s.groupEquations({0, 1});
  ASSERT_TRUE(s.analyze(A, false));
  EXPECT_EQ(s.activeName(), "block-lu");
  {
    BlockLuSolver b;
    b.groupEquations({0, 1});
    ASSERT_TRUE(b.analyze(A, false));
    const Status f = b.factorize(A);
    EXPECT_FALSE(f);
    EXPECT_TRUE(b.notStable());
  }
  const Status f = s.factorize(A);
  ASSERT_TRUE(f) << f.why;
  EXPECT_TRUE(s.fellBack());
  EXPECT_EQ(s.activeName(), "klu");
  const Eigen::Vector2d b(1.0, 2.0);
  Eigen::VectorXd x(2);
  ASSERT_TRUE(s.solve(b, x));
  EXPECT_LT(relResidual(A, x, b), 1e-15);
  // The pattern stays with KLU; a new analysis starts with the block LU again.
  A.coeffRef(0, 0) = 3.0;
  ASSERT_TRUE(s.factorize(A));
  EXPECT_EQ(s.activeName(), "klu");
  ASSERT_TRUE(s.analyze(A, false));
  EXPECT_EQ(s.activeName(), "block-lu");
  ASSERT_TRUE(s.factorize(A));
  ASSERT_TRUE(s.solve(b, x));
  EXPECT_LT(relResidual(A, x, b), 1e-15);
}

TEST(LinearSolverAuto, SingularFailsInBothAndSaysSo) {
  std::mt19937 rng(21);
  SparseMatrix A = laplacian1d(10, rng);
  for (int j = 0; j < A.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (it.row() == 4 || it.col() == 4) it.valueRef() = 0.0;
    }
  }
  AutoSolver s;
  ASSERT_TRUE(s.analyze(A, true));
  const Status f = s.factorize(A);
  EXPECT_FALSE(f);
  EXPECT_NE(f.why.find("cholmod"), std::string::npos) << f.why;
  EXPECT_NE(f.why.find("klu"), std::string::npos) << f.why;
  EXPECT_NE(f.why.find("singular"), std::string::npos) << f.why;
}

}  // namespace
}  // namespace c2d
