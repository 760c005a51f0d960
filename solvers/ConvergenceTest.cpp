#include "solvers/ConvergenceTest.h"

#include <algorithm>
#include <cmath>

namespace c2d {

bool ConvergenceTest::converged(const Figures& f) const {
  const double e0 = f.iteration == 1 ? f.energy : f.energy0;
  const double r0 = f.iteration == 1 ? f.residual : f.residual0;
  const bool stagnated = f.previousEnergy >= 0 && f.iteration >= 3 && f.energy <= 1e-10 * e0 &&
                         f.energy >= 0.1 * f.previousEnergy;
  const bool unresolvable = f.largestCorrection <= 1e-15 * f.positions;
  return e0 == 0 || f.energy <= energyTol * e0 || f.energy < energyZero ||
         (residualTol > 0 && f.residual <= residualTol * r0) || stagnated || unresolvable ||
         (!f.pathFollowing && f.largestResidual <= f.roundoff);
}

bool repeatsWithPeriod(const double* values, std::size_t n, int period, int matches,
                       double tolerance) {
  if (period < 1 || matches < 1 || n < static_cast<std::size_t>(matches + period)) return false;
  auto same = [&](std::size_t a, std::size_t b) {
    return std::abs(values[a] - values[b]) <=
           tolerance * std::max(std::abs(values[a]), std::abs(values[b]));
  };
  for (int k = 0; k < matches; ++k)
    if (!same(n - 1 - k, n - 1 - k - period)) return false;
  return true;
}

bool stopsProgressing(const double* values, std::size_t n, int maxPeriod, double tolerance) {
  for (int p = 1; p <= maxPeriod; ++p)
    if (repeatsWithPeriod(values, n, p, p, tolerance)) return true;
  return false;
}

bool runsAway(const double* residuals, std::size_t n) {
  if (n < 4) return false;
  for (std::size_t k = n - 2; k < n; ++k)
    if (!(residuals[k] > residuals[k - 1])) return false;
  const double least = *std::min_element(residuals + 1, residuals + n);
  return residuals[n - 1] > kDivergence * least;
}

}  // namespace c2d

