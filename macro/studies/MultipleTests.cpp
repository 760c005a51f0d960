#include "macro/studies/MultipleTests.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "macro/studies/PairedComparison.h"

namespace c2d {

double rankCorrelationP(double rho, int n) {
  if (std::isnan(rho) || n < 3) return NAN;
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
