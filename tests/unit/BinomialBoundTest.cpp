// The exact binomial bound of the sample-size rule (macro/studies/BinomialBound)
// by hand, beside Wilson's interval.
#include <gtest/gtest.h>

#include <cmath>

#include "macro/studies/BinomialBound.h"
#include "macro/studies/Statistics.h"

namespace c2d {
namespace {

// 0 of n at 95 %: the exact bound 1 - 0.05^(1/n) falls below 1 % at n = 299;
// Wilson's interval (z = 1.96), z^2/(n + z^2) < 0.01, only at n = 381.
TEST(SiteZones, SampleSizeRuleByHand) {
  EXPECT_NEAR(clopperPearsonUpper(0, 20, 0.95), 1 - std::pow(0.05, 1.0 / 20), 1e-14);
  EXPECT_NEAR(clopperPearsonUpper(0, 20, 0.95), 0.13911, 1e-5);
  EXPECT_NEAR(wilsonInterval(0, 20).second, 3.8416 / 23.8416, 1e-12);  // 0.161
  EXPECT_LT(clopperPearsonUpper(0, 299, 0.95), 0.01);
  EXPECT_GE(clopperPearsonUpper(0, 298, 0.95), 0.01);
  EXPECT_EQ(runsToShowBelow(0, 20, 0.01, 0.95), 299);
  EXPECT_EQ(runsToShowBelow(0, 400, 0.01, 0.95), 400);  // shown already
  int wilson = 1;
  while (wilsonInterval(0, wilson).second >= 0.01) ++wilson;
  EXPECT_EQ(wilson, 381);
  // 1 of 10: the one-sided 95 % bound solves P(X <= 1; 10, p) = 0.05, p = 0.3942.
  const double p = clopperPearsonUpper(1, 10, 0.95);
  EXPECT_NEAR(p, 0.39416, 1e-4);
  EXPECT_NEAR(std::pow(1 - p, 10) + 10 * p * std::pow(1 - p, 9), 0.05, 1e-9);
  EXPECT_DOUBLE_EQ(clopperPearsonUpper(3, 3, 0.95), 1.0);
  // One hit: the runs with no more hits that bring the bound below 1 %:
  // P(X <= 1; n, 0.01) = 0.05 first at n = 473.
  const long long n1 = runsToShowBelow(1, 20, 0.01, 0.95);
  EXPECT_LT(clopperPearsonUpper(1, static_cast<int>(n1), 0.95), 0.01);
  EXPECT_GE(clopperPearsonUpper(1, static_cast<int>(n1 - 1), 0.95), 0.01);
  EXPECT_EQ(n1, 473);
}

}  // namespace
}  // namespace c2d
