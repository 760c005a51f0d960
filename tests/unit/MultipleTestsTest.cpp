// The p-value of a rank correlation and Holm's correction of a family of tests,
// against values computed independently (R's p.adjust, scipy's spearmanr).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "macro/studies/MultipleTests.h"

namespace c2d {
namespace {

TEST(MultipleTests, HolmOnAKnownSet) {
  // R: p.adjust(c(0.01, 0.04, 0.03, 0.005), "holm") = 0.03 0.06 0.06 0.02: the
  // step-down products 4 (0.005), 3 (0.01), 2 (0.03), 1 (0.04), kept monotone.
  const std::vector<double> p = {0.01, 0.04, 0.03, 0.005};
  const std::vector<double> adj = holmAdjusted(p);
  const std::vector<double> expected = {0.03, 0.06, 0.06, 0.02};
  ASSERT_EQ(adj.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(adj[i], expected[i], 1e-15) << i;
}

TEST(MultipleTests, HolmSkipsUndefinedTestsAndCapsAtOne) {
  // Two tests only (the NaN is none): 2 x 0.02 = 0.04, then max(0.04, 0.7) = 0.7;
  // R: p.adjust(c(0.02, 0.7), "holm") = 0.04 0.70.
  const std::vector<double> adj = holmAdjusted(std::vector<double>{0.7, NAN, 0.02});
  EXPECT_NEAR(adj[0], 0.7, 1e-15);
  EXPECT_TRUE(std::isnan(adj[1]));
  EXPECT_NEAR(adj[2], 0.04, 1e-15);
  EXPECT_EQ(holmAdjusted(std::vector<double>{0.6, 0.9})[0], 1.0);  // 2 x 0.6 capped
}

TEST(MultipleTests, RankCorrelationPValue) {
  // scipy.stats.spearmanr's t approximation: rho = 0.6 over 10 runs, t =
  // 0.6 sqrt(8 / 0.64) = 2.1213 on 8 degrees of freedom: p = 0.066688.
  EXPECT_NEAR(rankCorrelationP(0.6, 10), 0.066688, 2e-6);
  EXPECT_NEAR(rankCorrelationP(-0.6, 10), rankCorrelationP(0.6, 10), 1e-15);
  EXPECT_NEAR(rankCorrelationP(0, 20), 1.0, 1e-12);
  // The exact law below ten pairs: n = 5, 1 of 120 orderings at rho = 1 and 4
  // more (one neighbour swap each) at rho = 0.9, either sign.
  EXPECT_NEAR(rankCorrelationP(1, 5), 2.0 / 120, 1e-15);
  EXPECT_NEAR(rankCorrelationP(-0.9, 5), 10.0 / 120, 1e-15);
  EXPECT_NEAR(rankCorrelationP(1, 3), 2.0 / 6, 1e-15);
  EXPECT_NEAR(rankCorrelationP(0, 4), 1.0, 1e-15);
  EXPECT_EQ(rankCorrelationP(1, 10), 0.0);
  EXPECT_TRUE(std::isnan(rankCorrelationP(0.5, 2)));
  EXPECT_TRUE(std::isnan(rankCorrelationP(NAN, 10)));
}

}  // namespace
}  // namespace c2d
