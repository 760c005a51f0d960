// Numeric factorization + solve time of the sparse direct solvers on the SPD
// stiffness matrix of a tall plane frame (20 bays, as many storeys as needed,
// fixed base; Euler-Bernoulli members, 3 dofs per node): banded, as the
// tangents of the analyses are. The symbolic analysis is done once, outside
// the timed loop, as in a Newton iteration.
#include <benchmark/benchmark.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "solvers/linear/LinearSolver.h"

namespace {

using c2d::SparseMatrix;

// Global stiffness of a member from (x1, y1) to (x2, y2). Units kN, m.
Eigen::Matrix<double, 6, 6> memberStiffness(double x1, double y1, double x2, double y2) {
  const double e = 30e6, area = 0.09, inertia = 6.75e-4;
  const double dx = x2 - x1, dy = y2 - y1, len = std::hypot(dx, dy);
  const double c = dx / len, s = dy / len;
  const double ea = e * area / len, ei = e * inertia;
  const double l2 = len * len, l3 = l2 * len;
  Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
  k(0, 0) = k(3, 3) = ea;
  k(0, 3) = k(3, 0) = -ea;
  k(1, 1) = k(4, 4) = 12 * ei / l3;
  k(1, 4) = k(4, 1) = -12 * ei / l3;
  k(1, 2) = k(2, 1) = k(1, 5) = k(5, 1) = 6 * ei / l2;
  k(4, 2) = k(2, 4) = k(4, 5) = k(5, 4) = -6 * ei / l2;
  k(2, 2) = k(5, 5) = 4 * ei / len;
  k(2, 5) = k(5, 2) = 2 * ei / len;
  Eigen::Matrix<double, 6, 6> t = Eigen::Matrix<double, 6, 6>::Zero();
  for (int n = 0; n < 2; ++n) {
    t(3 * n, 3 * n) = c;
    t(3 * n, 3 * n + 1) = s;
    t(3 * n + 1, 3 * n) = -s;
    t(3 * n + 1, 3 * n + 1) = c;
    t(3 * n + 2, 3 * n + 2) = 1;
  }
  return t.transpose() * k * t;
}

// About `unknowns` free dofs; base nodes (storey 0) are clamped and not numbered.
SparseMatrix frameStiffness(int unknowns) {
  const int bays = 20, perFloor = bays + 1;
  const int storeys = (unknowns + 3 * perFloor - 1) / (3 * perFloor);
  const double bay = 5.0, storey = 3.0;
  auto dof = [&](int col, int floor, int d) { return 3 * ((floor - 1) * perFloor + col) + d; };
  const int n = 3 * perFloor * storeys;
  std::vector<Eigen::Triplet<double, int>> trip;
  auto addMember = [&](int c1, int f1, int c2, int f2) {
    const auto k = memberStiffness(c1 * bay, f1 * storey, c2 * bay, f2 * storey);
    for (int a = 0; a < 6; ++a) {
      if (a < 3 ? f1 == 0 : f2 == 0) continue;
      const int ra = a < 3 ? dof(c1, f1, a) : dof(c2, f2, a - 3);
      for (int b = 0; b < 6; ++b) {
        if (b < 3 ? f1 == 0 : f2 == 0) continue;
        const int cb = b < 3 ? dof(c1, f1, b) : dof(c2, f2, b - 3);
        trip.emplace_back(ra, cb, k(a, b));
      }
    }
  };
  for (int f = 1; f <= storeys; ++f) {
    for (int c = 0; c < perFloor; ++c) {
      addMember(c, f - 1, c, f);                        // column
      if (c + 1 < perFloor) addMember(c, f, c + 1, f);  // beam
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  return A;
}

void factorizeAndSolve(benchmark::State& state, const std::string& name, bool grouped = false) {
  const SparseMatrix A = frameStiffness(static_cast<int>(state.range(0)));
  auto solver = c2d::makeLinearSolver(name);
  if (grouped && solver) {
    // The three dofs of a node together, as the analyses group them.
    std::vector<int> node(A.rows());
    for (int i = 0; i < A.rows(); ++i) node[i] = i / 3;
    solver->groupEquations(std::move(node));
  }
  if (!solver || !solver->analyze(A, true)) {
    state.SkipWithError("analysis failed");
    return;
  }
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  Eigen::VectorXd x(A.rows());
  for (auto _ : state) {
    if (!solver->factorize(A) || !solver->solve(b, x)) {
      state.SkipWithError("factorize or solve failed");
      return;
    }
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  state.counters["unknowns"] = static_cast<double>(A.rows());
  state.counters["relResidual"] = (A * x - b).norm() / b.norm();
}

}  // namespace

BENCHMARK_CAPTURE(factorizeAndSolve, cholmod, std::string("cholmod"))
    ->Arg(10000)
    ->Arg(40000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(factorizeAndSolve, umfpack, std::string("umfpack"))
    ->Arg(10000)
    ->Arg(40000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(factorizeAndSolve, klu, std::string("klu"))
    ->Arg(500)
    ->Arg(10000)
    ->Arg(40000)
    ->Unit(benchmark::kMillisecond);
// The block LU on the nodes' 3x3 blocks, as the analyses group them; against
// KLU's scalar refactorization above (the same pattern, new values, as in a
// Newton iteration), from the ten-storey decks' size (about 500 unknowns) up.
BENCHMARK_CAPTURE(factorizeAndSolve, block_lu, std::string("block-lu"), true)
    ->Arg(500)
    ->Arg(10000)
    ->Arg(40000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(factorizeAndSolve, eigen_ldlt, std::string("eigen-ldlt"))
    ->Arg(10000)
    ->Arg(40000)
    ->Unit(benchmark::kMillisecond);
