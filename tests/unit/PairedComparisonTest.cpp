// The paired comparison of two plans (macro/studies/PairedComparison): the
// incomplete beta and Student's t against closed forms and tables, the paired
// t-test and McNemar's test by hand, and the t-test at its edges.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "macro/studies/PairedComparison.h"

namespace c2d {
namespace {

TEST(EnsembleStatistics, PairedTestsByHand) {
  EXPECT_NEAR(incompleteBeta(2, 3, 0.4), 0.5248, 1e-14);
  // Closed forms: nu = 1 (Cauchy) 1/2 + atan(t)/pi; nu = 2: 1/2 + t / (2 sqrt(2 + t^2)).
  for (double t : {-3.0, -0.4, 0.7, 2.5, 40.0}) {
    EXPECT_NEAR(studentTCdf(t, 1), 0.5 + std::atan(t) / std::numbers::pi, 1e-14) << t;
    EXPECT_NEAR(studentTCdf(t, 2), 0.5 + t / (2 * std::sqrt(2 + t * t)), 1e-14) << t;
  }
  // Tables: t(0.975, 9) = 2.262157, t(0.975, 19) = 2.093024.
  EXPECT_NEAR(studentTCdf(2.262157, 9), 0.975, 1e-7);
  EXPECT_NEAR(studentTCdf(-2.093024, 19), 0.025, 1e-7);
  EXPECT_NEAR(studentTCdf(0, 4), 0.5, 1e-15);
  // d = 1, 2, 3, 4: mean 2.5, sd sqrt(5/3), t = 2.5 / (sd / 2) = 3.8730.
  const PairedTest t = pairedTTest(std::vector<double>{1, 2, 3, 4});
  EXPECT_NEAR(t.statistic, 2.5 / (std::sqrt(5.0 / 3) / 2), 1e-12);
  EXPECT_NEAR(t.p, 2 * (1 - studentTCdf(t.statistic, 3)), 1e-15);
  EXPECT_TRUE(t.significant());  // p = 0.0305
  // McNemar: b = 1, c = 9: p = 2 P(X <= 1), X ~ B(10, 1/2) = 2 * 11/1024.
  const PairedTest m = mcNemarTest(1, 9, 20);
  EXPECT_NEAR(m.p, 22.0 / 1024, 1e-15);
  EXPECT_NEAR(m.effect, 8.0 / 20, 1e-15);
  EXPECT_TRUE(m.significant());
  EXPECT_FALSE(mcNemarTest(3, 5, 20).significant());
  EXPECT_GT(mcNemarTest(3, 5, 20).samplesNeeded, 20);
  EXPECT_TRUE(std::isinf(mcNemarTest(2, 2, 20).samplesNeeded));
}

// The paired t-test at its edges: one pair is no test (t undefined, p = 1);
// two equal differences are no evidence (p = 1); three or more are certain.
TEST(EnsembleStatistics, PairedTestAtTheEdges) {
  const PairedTest one = pairedTTest(std::vector<double>{0.5});
  EXPECT_TRUE(std::isnan(one.statistic));
  EXPECT_EQ(one.p, 1.0);
  EXPECT_FALSE(one.significant());
  EXPECT_FALSE(pairedTTest(std::vector<double>{0.5, 0.5}).significant());
  EXPECT_TRUE(pairedTTest(std::vector<double>{0.5, 0.5, 0.5}).significant());
  EXPECT_FALSE(pairedTTest(std::vector<double>{0, 0, 0}).significant());
}

}  // namespace
}  // namespace c2d
