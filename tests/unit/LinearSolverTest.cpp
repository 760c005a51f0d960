// Every linear solver against dense LU/eigen solutions of the same systems:
// SPD graph-Laplacian matrices (1D chains and 2D grids, random sizes and
// weights), refactorization on a fixed pattern, indefinite, singular,
// unsymmetric and non-finite input.
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

namespace c2d {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

SparseMatrix fromTriplets(int n, const Triplets& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// Weighted graph Laplacian plus a positive diagonal: symmetric positive
// definite for any positive weights, with the pattern of the graph.
void addEdge(Triplets& t, int i, int j, double w) {
  t.emplace_back(i, i, w);
  t.emplace_back(j, j, w);
  t.emplace_back(i, j, -w);
  t.emplace_back(j, i, -w);
}

SparseMatrix laplacian1d(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> w(0.5, 2.0);
  Triplets t;
  for (int i = 0; i + 1 < n; ++i) addEdge(t, i, i + 1, w(rng));
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, 0.01 * w(rng));
  return fromTriplets(n, t);
}

SparseMatrix laplacian2d(int nx, int ny, std::mt19937& rng) {
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

Eigen::VectorXd randomVector(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = u(rng);
  return v;
}

Eigen::VectorXd denseSolve(const SparseMatrix& A, const Eigen::VectorXd& b) {
  return Eigen::MatrixXd(A).fullPivLu().solve(b);
}

double relResidual(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
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
