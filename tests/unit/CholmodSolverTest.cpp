// The CHOLMOD solver (solvers/linear/CholmodSolver): both methods detect
// indefiniteness and factorize again into a factor whose last factorization
// failed.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <string>

#include "solvers/linear/CholmodSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::denseSolve;
using test::laplacian2d;
using test::randomVector;

class LinearSolverCholmod : public ::testing::TestWithParam<CholmodSolver::Method> {};

// Both CHOLMOD methods detect indefiniteness and can factorize again into a
// factor whose last factorization failed.
TEST_P(LinearSolverCholmod, FailsOnIndefiniteThenRecovers) {
  std::mt19937 rng(22);
  const SparseMatrix spd = laplacian2d(15, 14, rng);
  SparseMatrix indefinite = spd;
  for (int j = 0; j < indefinite.outerSize(); ++j) indefinite.coeffRef(j, j) -= 0.5;
  CholmodSolver s(GetParam());
  ASSERT_TRUE(s.analyze(spd, true));
  if (GetParam() == CholmodSolver::Method::Supernodal) {
    EXPECT_TRUE(s.supernodal());
  } else if (GetParam() == CholmodSolver::Method::Simplicial) {
    EXPECT_FALSE(s.supernodal());
  }
  const Eigen::VectorXd b = randomVector(210, rng);
  Eigen::VectorXd x(210);
  for (int round = 0; round < 2; ++round) {
    ASSERT_TRUE(s.factorize(spd));
    ASSERT_TRUE(s.solve(b, x));
    EXPECT_LT((x - denseSolve(spd, b)).norm(), 1e-10 * x.norm());
    const Status f = s.factorize(indefinite);
    EXPECT_FALSE(f);
    EXPECT_TRUE(s.notPositiveDefinite());
    EXPECT_NE(f.why.find("not positive definite"), std::string::npos) << f.why;
    EXPECT_FALSE(s.solve(b, x));
  }
}

INSTANTIATE_TEST_SUITE_P(LinearSolver, LinearSolverCholmod,
                         ::testing::Values(CholmodSolver::Method::Automatic,
                                           CholmodSolver::Method::Simplicial,
                                           CholmodSolver::Method::Supernodal));

}  // namespace
}  // namespace c2d
