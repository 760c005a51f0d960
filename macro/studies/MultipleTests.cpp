#include "macro/studies/MultipleTests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "macro/studies/PairedComparison.h"

namespace c2d {

namespace {

// |rho| of every ordering of n untied ranks, sorted (n! values, n < kExactRankPairs).
const std::vector<double>& permutationLaw(int n) {
  static std::array<std::vector<double>, kExactRankPairs> laws;
  std::vector<double>& law = laws[static_cast<std::size_t>(n)];
  if (law.empty()) {
    std::vector<int> perm(static_cast<std::size_t>(n));
    std::iota(perm.begin(), perm.end(), 0);
    const double scale = 6.0 / (n * (static_cast<double>(n) * n - 1));
    do {
      double s = 0;
      for (int i = 0; i < n; ++i) s += (perm[i] - i) * (perm[i] - i);
      law.push_back(std::abs(1 - scale * s));
    } while (std::next_permutation(perm.begin(), perm.end()));
    std::sort(law.begin(), law.end());
  }
  return law;
}

}  // namespace

double rankCorrelationP(double rho, int n) {
  if (std::isnan(rho) || n < 3) return NAN;
  if (n < kExactRankPairs) {
    const std::vector<double>& law = permutationLaw(n);
    // Ties give values between the untied ones: reaching |rho| up to round-off counts.
    const auto first = std::lower_bound(law.begin(), law.end(), std::abs(rho) - 1e-12);
    return static_cast<double>(law.end() - first) / static_cast<double>(law.size());
  }
  if (std::abs(rho) >= 1) return 0;
  const double nu = n - 2;
  const double t = std::abs(rho) * std::sqrt(nu / (1 - rho * rho));
  return std::min(1.0, 2 * (1 - studentTCdf(t, nu)));
}

std::vector<double> holmAdjusted(std::span<const double> p) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isnan(p[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adj(p.size(), NAN);
  const double m = static_cast<double>(order.size());
  double running = 0;
  for (std::size_t j = 0; j < order.size(); ++j) {
    running = std::max(running, std::min(1.0, (m - static_cast<double>(j)) * p[order[j]]));
    adj[order[j]] = running;
  }
  return adj;
}

}  // namespace c2d
