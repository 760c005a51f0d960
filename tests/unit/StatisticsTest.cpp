// The statistics of an ensemble (macro/studies/Statistics): quantiles, the
// Wilson interval and the rank correlation against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "macro/studies/Statistics.h"

namespace c2d {
namespace {

TEST(EnsembleStatistics, QuantilesByHand) {
  const std::vector<double> x = {4, 1, 3, 2};
  EXPECT_NEAR(quantile(x, 0.1), 1.3, 1e-15);
  EXPECT_NEAR(quantile(x, 0.5), 2.5, 1e-15);
  EXPECT_NEAR(quantile(x, 0.9), 3.7, 1e-15);
  EXPECT_EQ(quantile(x, 0), 1);
  EXPECT_EQ(quantile(x, 1), 4);
  EXPECT_EQ(quantile(std::vector<double>{5}, 0.3), 5);
  EXPECT_TRUE(std::isnan(quantile(std::vector<double>{}, 0.5)));
}

TEST(EnsembleStatistics, WilsonIntervalByHand) {
  // (p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n), z = 1.96.
  auto [lo, hi] = wilsonInterval(7, 20);
  EXPECT_NEAR(lo, 0.18118954786794464, 1e-15);
  EXPECT_NEAR(hi, 0.5671494897805354, 1e-15);
  std::tie(lo, hi) = wilsonInterval(0, 10);
  EXPECT_EQ(lo, 0);
  EXPECT_NEAR(hi, 0.2775401687666166, 1e-15);
  std::tie(lo, hi) = wilsonInterval(10, 10);
  EXPECT_NEAR(lo, 0.7224598312333834, 1e-15);
  EXPECT_EQ(hi, 1);
}

TEST(EnsembleStatistics, RankCorrelationByHand) {
  // Ties get their mean rank: y's ranks 1, 2, 3.5, 5, 3.5.
  EXPECT_NEAR(
      rankCorrelation(std::vector<double>{1, 2, 3, 4, 5}, std::vector<double>{5, 6, 7, 8, 7}),
      0.8207826816681233, 1e-14);
  // Without ties, 1 - 6 sum d^2 / (n (n^2 - 1)) = 1 - 6 * 16 / 210.
  EXPECT_NEAR(rankCorrelation(std::vector<double>{0.3, 0.1, 0.2, 0.5, 0.4, 0.6},
                              std::vector<double>{2.0, 1.0, 1.5, 1.2, 3.0, 2.5}),
              1 - 6.0 * 16 / 210, 1e-14);
  EXPECT_NEAR(rankCorrelation(std::vector<double>{1, 2, 3}, std::vector<double>{1, 8, 27}), 1,
              1e-15);
  EXPECT_NEAR(rankCorrelation(std::vector<double>{1, 2, 3}, std::vector<double>{3, 2, 1}), -1,
              1e-15);
  EXPECT_TRUE(
      std::isnan(rankCorrelation(std::vector<double>{1, 2, 3}, std::vector<double>{4, 4, 4})));
}

}  // namespace
}  // namespace c2d
