// The laws an ensemble draws from (macro/studies/Distribution): the samplers
// against their distributions (Kolmogorov-Smirnov) and the normal quantile
// against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "macro/draws/CounterRandom.h"
#include "macro/draws/Distribution.h"
#include "tests/unit/EnsembleTestSupport.h"

namespace c2d {
namespace {

using testing::ksCritical;
using testing::ksStatistic;

// n draws of the law, as an ensemble makes them: sample k = 1..n, seed 7.
std::vector<double> draws(const Distribution& law, int n, const char* name = "x") {
  std::vector<double> x;
  for (int k = 1; k <= n; ++k) x.push_back(law.quantile(counterUniform(7, k, streamOf(name), 0)));
  return x;
}

TEST(EnsembleSamplers, DrawsFollowTheirDistributions) {
  constexpr int n = 2000;
  const Distribution normal{Law::Normal, 3, 0.5}, logn{Law::LogNormal, 2, 0.3},
      uniform{Law::Uniform, 0.4, 0.6};
  for (const Distribution& law : {normal, logn, uniform}) {
    const std::vector<double> x = draws(law, n);
    EXPECT_LT(ksStatistic(x, [&](double v) { return law.cdf(v); }), ksCritical(n)) << law.text();
  }
  // The test tells a wrong law: the normal draws against a normal of another mean.
  const Distribution shifted{Law::Normal, 3.1, 0.5};
  EXPECT_GT(ksStatistic(draws(normal, n), [&](double v) { return shifted.cdf(v); }), ksCritical(n));
  // The lognormal's median and coefficient of variation.
  std::vector<double> x = draws(logn, n, "y");
  std::sort(x.begin(), x.end());
  EXPECT_NEAR(x[n / 2], 2, 0.05);
  double mean = 0, var = 0;
  for (double v : x) mean += v / n;
  for (double v : x) var += (v - mean) * (v - mean) / (n - 1);
  EXPECT_NEAR(std::sqrt(var) / mean, 0.3, 0.02);
  // The uniform numbers themselves, and a stream independent of another's.
  std::vector<double> u, v;
  for (int k = 1; k <= n; ++k) {
    u.push_back(counterUniform(1, k, streamOf("a"), 0));
    v.push_back(counterUniform(1, k, streamOf("b"), 0));
  }
  EXPECT_LT(ksStatistic(u, [](double t) { return t; }), ksCritical(n));
  double cov = 0;
  for (int k = 0; k < n; ++k) cov += (u[k] - 0.5) * (v[k] - 0.5) / n;
  EXPECT_LT(std::abs(cov / (1.0 / 12)), 3 / std::sqrt(static_cast<double>(n)));
}

TEST(EnsembleSamplers, NormalQuantileByHand) {
  EXPECT_NEAR(normalQuantile(0.975), 1.9599639845400536, 1e-14);
  EXPECT_NEAR(normalQuantile(0.3), -0.5244005127080407, 1e-14);
  EXPECT_NEAR(normalQuantile(0.001), -3.090232306167813, 1e-13);
  EXPECT_NEAR(normalQuantile(1e-10), -6.361340902404056, 1e-12);
  EXPECT_NEAR(normalQuantile(0.5), 0, 1e-16);
  for (double p : {1e-300, 1e-6, 0.2, 0.7, 1 - 1e-9})
    EXPECT_NEAR(normalCdf(normalQuantile(p)) / p, 1, 1e-12);
}

}  // namespace
}  // namespace c2d
