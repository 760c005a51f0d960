// Every linear solver (solvers/linear/LinearSolver's factory) against dense LU
// solutions of the same systems: SPD graph-Laplacian matrices (1D chains and
// 2D grids, random sizes and weights), refactorization on a fixed pattern,
// indefinite, singular, unsymmetric and non-finite input. Each solver's own
// behaviour: AutoSolverTest, BlockLuSolverTest, CholmodSolverTest, KluSolverTest.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "solvers/linear/AutoSolver.h"
#include "solvers/linear/BlockLuSolver.h"
#include "solvers/linear/CholmodSolver.h"
#include "solvers/linear/KluSolver.h"
#include "solvers/linear/LinearSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::denseSolve;
using test::fromTriplets;
using test::laplacian1d;
using test::laplacian2d;
using test::randomVector;
using test::relResidual;
using test::Triplets;

// Same pattern, new values: every stored value scaled by its own random factor,
// symmetrically, keeping the diagonal dominant so the matrix stays SPD.
SparseMatrix perturbSymmetric(const SparseMatrix& A, std::mt19937& rng) {
  std::uniform_real_distribution<double> f(0.5, 1.5);
  SparseMatrix B = A;
  for (int j = 0; j < B.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(B, j); it; ++it) {
      if (it.row() < it.col()) it.valueRef() *= f(rng);
    }
  }
  // Mirror the upper triangle and rebuild the diagonal as a weighted Laplacian's.
  Eigen::VectorXd offSum = Eigen::VectorXd::Zero(B.rows());
  for (int j = 0; j < B.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(B, j); it; ++it) {
      if (it.row() > it.col()) it.valueRef() = B.coeff(it.col(), it.row());
      if (it.row() != it.col()) offSum(it.row()) += std::abs(it.value());
    }
  }
  for (int j = 0; j < B.outerSize(); ++j) B.coeffRef(j, j) = offSum(j) + 0.01 * f(rng);
  return B;
}

bool isSymmetricSolverOnly(const std::string& name) {
  return name == "cholmod" || name == "eigen-ldlt";
}

class LinearSolverEach : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<LinearSolver> make() {
    auto s = makeLinearSolver(GetParam());
    EXPECT_NE(s, nullptr);
    return s;
  }

  // Analyze, factorize, solve, and compare with the dense solution.
  void expectSolves(LinearSolver& s, const SparseMatrix& A, bool symmetric, std::mt19937& rng) {
    const Status a = s.analyze(A, symmetric);
    ASSERT_TRUE(a) << a.why;
    expectRefactorSolves(s, A, rng);
  }

  void expectRefactorSolves(LinearSolver& s, const SparseMatrix& A, std::mt19937& rng) {
    const Status f = s.factorize(A);
    ASSERT_TRUE(f) << f.why;
    const Eigen::VectorXd b = randomVector(static_cast<int>(A.rows()), rng);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
    const Status r = s.solve(b, x);
    ASSERT_TRUE(r) << r.why;
    const Eigen::VectorXd ref = denseSolve(A, b);
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm());
    EXPECT_LT(relResidual(A, x, b), 1e-12);
  }
};

TEST_P(LinearSolverEach, NameRoundTrips) {
  auto s = make();
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->name(), GetParam());
}

TEST_P(LinearSolverEach, Spd1dMatchesDense) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> size(2, 300);
  for (int k = 0; k < 4; ++k) {
    auto s = make();
    expectSolves(*s, laplacian1d(size(rng), rng), true, rng);
  }
}

TEST_P(LinearSolverEach, Spd2dMatchesDense) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> size(2, 17);
  for (int k = 0; k < 4; ++k) {
    auto s = make();
    expectSolves(*s, laplacian2d(size(rng), size(rng), rng), true, rng);
  }
}

TEST_P(LinearSolverEach, RefactorizeWithNewValuesOnSamePattern) {
  std::mt19937 rng(13);
  auto s = make();
  SparseMatrix A = laplacian2d(12, 9, rng);
  const SparseMatrix A0 = A;
  ASSERT_TRUE(s->analyze(A, true));
  for (int k = 0; k < 4; ++k) {
    expectRefactorSolves(*s, A, rng);
    A = perturbSymmetric(A, rng);
  }
  // The factors follow the values: the first matrix again gives its own solution.
  expectRefactorSolves(*s, A0, rng);
}

TEST_P(LinearSolverEach, SolveInPlaceAndSizeChecks) {
  std::mt19937 rng(14);
  auto s = make();
  const SparseMatrix A = laplacian2d(7, 6, rng);
  ASSERT_TRUE(s->analyze(A, true));
  ASSERT_TRUE(s->factorize(A));
  const Eigen::VectorXd b = randomVector(42, rng);
  Eigen::VectorXd x = b;
  ASSERT_TRUE(s->solve(x, x));
  EXPECT_LT(relResidual(A, x, b), 1e-12);
  Eigen::VectorXd wrong(41);
  EXPECT_FALSE(s->solve(b, wrong));
  Eigen::VectorXd bad = b;
  bad(3) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(s->solve(bad, x));
}

TEST_P(LinearSolverEach, IndefiniteSymmetric) {
  std::mt19937 rng(15);
  SparseMatrix A = laplacian2d(9, 8, rng);
  // Shift between two eigenvalues: symmetric, nonsingular, indefinite.
  const Eigen::VectorXd ev =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
  const double shift = 0.5 * (ev(20) + ev(21));
  for (int j = 0; j < A.outerSize(); ++j) A.coeffRef(j, j) -= shift;
  auto s = make();
  ASSERT_TRUE(s->analyze(A, true));
  const Status f = s->factorize(A);
  if (GetParam() == "cholmod") {
    EXPECT_FALSE(f);
    EXPECT_NE(f.why.find("not positive definite"), std::string::npos) << f.why;
    Eigen::VectorXd x(A.rows());
    EXPECT_FALSE(s->solve(randomVector(static_cast<int>(A.rows()), rng), x));
    // The failed factor is reusable: the SPD matrix on the same pattern factorizes.
    for (int j = 0; j < A.outerSize(); ++j) A.coeffRef(j, j) += shift;
    expectRefactorSolves(*s, A, rng);
    return;
  }
  ASSERT_TRUE(f) << f.why;
  const Eigen::VectorXd b = randomVector(static_cast<int>(A.rows()), rng);
  Eigen::VectorXd x(A.rows());
  ASSERT_TRUE(s->solve(b, x));
  EXPECT_LT((x - denseSolve(A, b)).norm(), 1e-8 * x.norm());
  EXPECT_LT(relResidual(A, x, b), 1e-10);
}

TEST_P(LinearSolverEach, SingularIsAFailure) {
  std::mt19937 rng(16);
  SparseMatrix A = laplacian2d(6, 5, rng);
  // Zero row and column 7 with the pattern kept: rank n-1, exact zero pivot.
  const int k = 7;
  for (int j = 0; j < A.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (it.row() == k || it.col() == k) it.valueRef() = 0.0;
    }
  }
  auto s = make();
  ASSERT_TRUE(s->analyze(A, true));
  const Status f = s->factorize(A);
  EXPECT_FALSE(f);
  EXPECT_FALSE(f.why.empty());
  // The Cholesky names the dof whose pivot vanished.
  if (GetParam() == "cholmod") {
    EXPECT_NE(f.why.find("row 7 "), std::string::npos) << f.why;
  }
  Eigen::VectorXd x(A.rows());
  EXPECT_FALSE(s->solve(randomVector(static_cast<int>(A.rows()), rng), x));
}

TEST_P(LinearSolverEach, NonFiniteMatrixIsAFailure) {
  std::mt19937 rng(17);
  SparseMatrix A = laplacian1d(20, rng);
  auto s = make();
  ASSERT_TRUE(s->analyze(A, true));
  A.coeffRef(4, 5) = std::numeric_limits<double>::quiet_NaN();
  const Status f = s->factorize(A);
  EXPECT_FALSE(f);
  EXPECT_NE(f.why.find("non-finite"), std::string::npos) << f.why;
  EXPECT_NE(f.why.find("row 4, column 5"), std::string::npos) << f.why;
}

TEST_P(LinearSolverEach, ChangedPatternNeedsAnalyze) {
  std::mt19937 rng(18);
  auto s = make();
  const SparseMatrix A = laplacian1d(30, rng);
  ASSERT_TRUE(s->analyze(A, true));
  const Status f = s->factorize(laplacian2d(6, 5, rng));
  EXPECT_FALSE(f);
  EXPECT_NE(f.why.find("pattern"), std::string::npos) << f.why;
  EXPECT_FALSE(make()->factorize(A));  // never analyzed
  // A new analysis accepts the new pattern.
  expectSolves(*s, laplacian2d(6, 5, rng), true, rng);
}

TEST_P(LinearSolverEach, Unsymmetric) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 150;
  // Convection-diffusion-like: unsymmetric in values and in pattern.
  Triplets t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + 0.1 * u(rng));
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0 + 0.5 * u(rng));
    if (i > 0) t.emplace_back(i, i - 1, -0.3 + 0.2 * u(rng));
    if (i + 7 < n) t.emplace_back(i + 7, i, u(rng));
  }
  SparseMatrix A = fromTriplets(n, t);
  auto s = make();
  if (isSymmetricSolverOnly(GetParam())) {
    const Status a = s->analyze(A, false);
    EXPECT_FALSE(a);
    EXPECT_NE(a.why.find("symmetric"), std::string::npos) << a.why;
    return;
  }
  expectSolves(*s, A, false, rng);
  // A zero diagonal forces off-diagonal pivots.
  for (int i = 0; i < n; i += 3) A.coeffRef(i, i) = 0.0;
  if (GetParam() == "block-lu") {
    // Each equation its own block (no grouping): no pivot to choose.
    const Status f = s->factorize(A);
    EXPECT_FALSE(f);
    EXPECT_NE(f.why.find("no pivoting"), std::string::npos) << f.why;
    return;
  }
  expectRefactorSolves(*s, A, rng);
}

INSTANTIATE_TEST_SUITE_P(LinearSolver, LinearSolverEach, ::testing::ValuesIn(linearSolverNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n) {
                             if (c == '-') c = '_';
                           }
                           return n;
                         });

TEST(LinearSolverFactory, UnknownNameGivesNull) {
  EXPECT_EQ(makeLinearSolver("pardiso"), nullptr);
  EXPECT_EQ(makeLinearSolver(""), nullptr);
  EXPECT_EQ(makeLinearSolver("Cholmod"), nullptr);
  EXPECT_EQ(linearSolverNames().front(), "auto");
}

}  // namespace
}  // namespace c2d
