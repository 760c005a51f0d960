// solvers/linear/CheckedSolve: a correction that misses K du = R is refined, then
// factored again with pivoting, before the tangent is called singular; the
// diagnosis tells an ill-conditioned tangent from a singular one by the
// condition number estimate.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "solvers/linear/AutoSolver.h"
#include "solvers/linear/CheckedSolve.h"
#include "solvers/linear/KluSolver.h"
#include "tests/unit/LinearSolverTestSupport.h"

namespace c2d {
namespace {

using test::fromTriplets;
using test::Triplets;

// A nonsymmetric, diagonally dominant chain (condition number of order ten).
SparseMatrix chain(int n) {
  Triplets t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0 + 0.1 * i);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0 - 0.01 * i), t.emplace_back(i + 1, i, -0.7);
  }
  return fromTriplets(n, t);
}

// Factors of a perturbed copy of the matrix (each entry off by up to a
// relative eta): its solves miss, as a factorization that lost digits would.
// refactorWithPivoting factors the matrix itself, once, when allowed.
class InexactSolver final : public LinearSolver {
 public:
  InexactSolver(double eta, bool canPivot) : eta_(eta), canPivot_(canPivot) {}
  std::string name() const override { return "inexact"; }
  Status analyze(const SparseMatrix& A, bool symmetric) override {
    return klu_.analyze(A, symmetric);
  }
  Status factorize(const SparseMatrix& A) override {
    SparseMatrix B = A;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-eta_, eta_);
    for (int k = 0; k < B.nonZeros(); ++k) B.valuePtr()[k] *= 1 + u(rng);
    return klu_.factorize(B);
  }
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override { return klu_.solve(b, x); }
  bool refactorWithPivoting(const SparseMatrix& A) override {
    if (!canPivot_) return false;
    canPivot_ = false;
    return static_cast<bool>(klu_.factorize(A));
  }
  double conditionEstimate(const SparseMatrix& A) override { return klu_.conditionEstimate(A); }

 private:
  KluSolver klu_;
  double eta_;
  bool canPivot_;
};

struct Outcome {
  CheckedSolve check;
  Status status;
  double misfit = 0;  // |K du - R| / |R| of the correction returned
};

Outcome solveChecked(LinearSolver& s, const SparseMatrix& K, const Eigen::VectorXd& R) {
  Outcome r;
  EXPECT_TRUE(s.analyze(K, false));
  EXPECT_TRUE(s.factorize(K));
  Eigen::VectorXd du(R.size()), rho, drho;
  EXPECT_TRUE(s.solve(R, du));
  r.status = r.check.check(s, K, R, du, rho, drho);
  r.misfit = (K * du - R).norm() / R.norm();
  return r;
}

TEST(CheckedSolve, AnExactSolvePassesUntouched) {
  const SparseMatrix K = chain(12);
  const Eigen::VectorXd R = Eigen::VectorXd::LinSpaced(12, 1.0, 3.0);
  KluSolver klu;
  const Outcome r = solveChecked(klu, K, R);
  ASSERT_TRUE(r.status) << r.status.why;
  EXPECT_EQ(r.check.refinements, 0);
  EXPECT_FALSE(r.check.pivoted);
  EXPECT_LT(r.misfit, 1e-14);
}

TEST(CheckedSolve, ASolveThatMissesIsRefinedWithTheSameFactors) {
  // Factors off by 1e-4: the first solve misses by about that much, and each
  // sweep of refinement gains four digits.
  const SparseMatrix K = chain(12);
  const Eigen::VectorXd R = Eigen::VectorXd::LinSpaced(12, 1.0, 3.0);
  InexactSolver s(1e-4, false);
  const Outcome r = solveChecked(s, K, R);
  ASSERT_TRUE(r.status) << r.status.why;
  EXPECT_GE(r.check.refinements, 1);
  EXPECT_FALSE(r.check.pivoted);
  EXPECT_LE(r.misfit, CheckedSolve::kMaxMisfit);
  EXPECT_EQ(r.misfit, r.check.misfit);
}

TEST(CheckedSolve, WhenRefinementDoesNotReachTheSolveIsFactoredAgainWithPivoting) {
  // Factors off by 30 %: refinement contracts too slowly for three sweeps.
  const SparseMatrix K = chain(12);
  const Eigen::VectorXd R = Eigen::VectorXd::LinSpaced(12, 1.0, 3.0);
  InexactSolver s(0.3, true);
  const Outcome r = solveChecked(s, K, R);
  ASSERT_TRUE(r.status) << r.status.why;
  EXPECT_TRUE(r.check.pivoted);
  EXPECT_LE(r.misfit, CheckedSolve::kMaxMisfit);
}

TEST(CheckedSolve, AWellConditionedTangentThatStillMissesIsNotCalledSingular) {
  // No pivoting fallback and no refinement that reaches: the failure, with
  // a condition number of order ten, is not a mechanism.
  const SparseMatrix K = chain(12);
  const Eigen::VectorXd R = Eigen::VectorXd::LinSpaced(12, 1.0, 3.0);
  InexactSolver s(0.3, false);
  const Outcome r = solveChecked(s, K, R);
  EXPECT_FALSE(r.status);
  EXPECT_FALSE(r.check.singular);
  EXPECT_GT(r.check.condition, 1.0);
  EXPECT_LT(r.check.condition, 1e3);
  EXPECT_EQ(r.check.diagnosis().rfind("ill-conditioned tangent (condition number estimate", 0), 0u)
      << r.check.diagnosis();
}

TEST(CheckedSolve, ASingularTangentIsCalledSingular) {
  // Rank two: the rows are in arithmetic progression. The nodes' block LU
  // finds its one block singular and the auto solver goes to KLU, which ends
  // with a round-off pivot; its correction solves nothing, no refinement
  // helps, KLU's pivots were fresh, and the condition estimate is of order
  // 1 / eps.
  Triplets t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.emplace_back(i, j, 0.1 * (3 * i + j + 1));
  const SparseMatrix K = fromTriplets(3, t);
  AutoSolver s;
  s.groupEquations({0, 0, 0});
  ASSERT_TRUE(s.analyze(K, false));
  const Status f = s.factorize(K);
  if (!f) GTEST_SKIP() << "KLU met an exact zero pivot: " << f.why;
  EXPECT_EQ(s.activeName(), "klu");
  const Eigen::Vector3d R(1.0, -2.0, 0.5);
  Eigen::VectorXd du(3), rho, drho;
  ASSERT_TRUE(s.solve(R, du));
  CheckedSolve check;
  EXPECT_FALSE(check.check(s, K, R, du, rho, drho));
  EXPECT_FALSE(check.pivoted);
  EXPECT_TRUE(check.singular);
  EXPECT_GE(check.condition, CheckedSolve::kSingularCondition);
  EXPECT_EQ(check.diagnosis().rfind("singular tangent: the solve leaves", 0), 0u)
      << check.diagnosis();
  EXPECT_NE(check.diagnosis().find("a mechanism?; condition number estimate"), std::string::npos)
      << check.diagnosis();
}

TEST(CheckedSolve, TheAutoSolverFallsBackFromTheBlockLuToKluOnRequest) {
  // A pivoting factorization asked of the auto solver while the block LU is
  // active: KLU factors the matrix and stays for the pattern; its condition
  // estimate is then available (the block LU has none).
  const SparseMatrix K = chain(9);
  AutoSolver s;
  s.groupEquations({0, 0, 0, 1, 1, 1, 2, 2, 2});
  ASSERT_TRUE(s.analyze(K, false));
  ASSERT_TRUE(s.factorize(K));
  EXPECT_EQ(s.activeName(), "block-lu");
  EXPECT_LT(s.conditionEstimate(K), 0);
  ASSERT_TRUE(s.refactorWithPivoting(K));
  EXPECT_EQ(s.activeName(), "klu");
  EXPECT_TRUE(s.fellBack());
  const double c = s.conditionEstimate(K);
  EXPECT_GT(c, 1.0);
  EXPECT_LT(c, 1e3);
  // KLU's factors of the same pattern reuse the pivot order: asked again, a
  // fresh pivot search; after it nothing better is left to try.
  ASSERT_TRUE(s.factorize(K));
  EXPECT_EQ(s.activeName(), "klu");
  EXPECT_TRUE(s.refactorWithPivoting(K));
  EXPECT_FALSE(s.refactorWithPivoting(K));
}

}  // namespace
}  // namespace c2d
