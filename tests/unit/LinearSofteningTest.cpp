// Rigid-plastic softening hinge in series with an elastic spring (paper eqs 34-38).
#include "materials/LinearSoftening.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace c2d {
namespace {

constexpr double kMu = 274, kKs = -18000;
constexpr double kK = 77650 / 0.5;  // EI/l_e of a 0.5 m element

TEST(LinearSoftening, CapacityDecreasesLinearlyToZero) {
  const LinearSoftening law(kMu, kKs);
  EXPECT_DOUBLE_EQ(law.capacity(0), kMu);
  EXPECT_NEAR(law.capacity(0.005), kMu + kKs * 0.005, 1e-12);
  EXPECT_DOUBLE_EQ(law.failureJump(), kMu / 18000);
  EXPECT_EQ(law.capacity(0.02), 0.0);
  EXPECT_TRUE(law.exhausted(0.02));
  EXPECT_FALSE(law.exhausted(0.01));
}

TEST(LinearSoftening, RigidBelowCapacity) {
  const LinearSoftening law(kMu, kKs);
  const SofteningState s{0.002, 0.002};
  SofteningResponse r;
  ASSERT_TRUE(law.returnMap(s, 200.0, kK, r));
  EXPECT_DOUBLE_EQ(r.t, 200.0);
  EXPECT_DOUBLE_EQ(r.tangent, 1.0);
  EXPECT_FALSE(r.loading);
  EXPECT_EQ(r.state.alpha, s.alpha);
  EXPECT_EQ(r.state.xi, s.xi);
  // Reverse moment below the capacity: also rigid.
  ASSERT_TRUE(law.returnMap(s, -200.0, kK, r));
  EXPECT_FALSE(r.loading);
}

TEST(LinearSoftening, SofteningBranchHandValues) {
  const LinearSoftening law(kMu, kKs);
  SofteningResponse r;
  const double mt = 280.0;
  ASSERT_TRUE(law.returnMap({}, mt, kK, r));
  // t = mt - k*alpha and t = Mu + Ks*alpha.
  const double alpha = (mt - kMu) / (kK + kKs);
  EXPECT_NEAR(r.state.alpha, alpha, 1e-15);
  EXPECT_NEAR(r.state.xi, alpha, 1e-15);
  EXPECT_NEAR(r.t, kMu + kKs * alpha, 1e-10);
  EXPECT_NEAR(r.t, mt - kK * alpha, 1e-10);
  EXPECT_NEAR(r.tangent, kKs / (kK + kKs), 1e-15);
  EXPECT_TRUE(r.loading);
  EXPECT_FALSE(r.failed);

  // Negative direction from a partly softened state.
  const SofteningState s{-0.003, 0.003};
  ASSERT_TRUE(law.returnMap(s, -300.0, kK, r));
  const double dg = (300.0 - law.capacity(0.003)) / (kK + kKs);
  EXPECT_NEAR(r.state.alpha, -0.003 - dg, 1e-15);
  EXPECT_NEAR(r.t, -law.capacity(0.003 + dg), 1e-10);
}

TEST(LinearSoftening, UnloadingAfterSofteningKeepsTheJump) {
  const LinearSoftening law(kMu, kKs);
  SofteningResponse r;
  ASSERT_TRUE(law.returnMap({}, 1000.0, kK, r));
  const SofteningState s = r.state;
  const double cap = law.capacity(s.xi);
  ASSERT_TRUE(law.returnMap(s, 0.9 * cap, kK, r));
  EXPECT_FALSE(r.loading);
  EXPECT_EQ(r.state.alpha, s.alpha);
  // Reloading past the reduced capacity softens further.
  ASSERT_TRUE(law.returnMap(s, 1.1 * cap, kK, r));
  EXPECT_TRUE(r.loading);
  EXPECT_GT(r.state.xi, s.xi);
  EXPECT_NEAR(std::abs(r.t), law.capacity(r.state.xi), 1e-9);
}

TEST(LinearSoftening, CompleteFailureGivesAFreeHinge) {
  const LinearSoftening law(kMu, kKs);
  SofteningResponse r;
  // A trial moment large enough to exhaust the capacity in one step.
  const double mt = kMu + kK * 0.03;
  ASSERT_TRUE(law.returnMap({}, mt, kK, r));
  EXPECT_TRUE(r.failed);
  EXPECT_EQ(r.t, 0.0);
  EXPECT_EQ(r.tangent, 0.0);
  EXPECT_NEAR(r.state.alpha, mt / kK, 1e-15);
  EXPECT_GT(r.state.xi, law.failureJump());
  // Exactly at the boundary the two branches agree.
  const double mf = kK * law.failureJump();
  ASSERT_TRUE(law.returnMap({}, mf * (1 - 1e-12), kK, r));
  EXPECT_NEAR(r.t, 0.0, 1e-6);
  EXPECT_NEAR(r.state.alpha, law.failureJump(), 1e-12);
  // After failure every trial moment is carried by the jump.
  const SofteningState s{0.02, 0.02};
  ASSERT_TRUE(law.returnMap(s, -50.0, kK, r));
  EXPECT_EQ(r.t, 0.0);
  EXPECT_NEAR(r.state.alpha, 0.02 - 50.0 / kK, 1e-15);
}

TEST(LinearSoftening, TangentMatchesFiniteDifferences) {
  const LinearSoftening law(kMu, kKs);
  const SofteningState states[] = {{}, {0.004, 0.004}, {-0.01, 0.012}, {0.02, 0.02}};
  for (const SofteningState& s : states) {
    for (double mt : {100.0, 290.0, -290.0, 1500.0, 5000.0}) {
      SofteningResponse r, rp, rm;
      const double h = 1e-5;
      ASSERT_TRUE(law.returnMap(s, mt, kK, r));
      ASSERT_TRUE(law.returnMap(s, mt + h, kK, rp));
      ASSERT_TRUE(law.returnMap(s, mt - h, kK, rm));
      EXPECT_NEAR(r.tangent, (rp.t - rm.t) / (2 * h), 1e-7) << "alpha " << s.alpha << " mt " << mt;
    }
  }
}

TEST(LinearSoftening, FailsWhenTheSpringIsTooSoft) {
  const LinearSoftening law(kMu, kKs);
  SofteningResponse r;
  EXPECT_FALSE(law.returnMap({}, 300.0, 10000.0, r));
  // An exhausted hinge has no softening left: any positive spring will do.
  EXPECT_TRUE(law.returnMap({0.02, 0.02}, 300.0, 10000.0, r));
}

TEST(LinearSoftening, RejectsInconsistentParameters) {
  EXPECT_THROW(LinearSoftening(kMu, 100.0), std::invalid_argument);
  EXPECT_THROW(LinearSoftening(0.0, kKs), std::invalid_argument);
}

}  // namespace
}  // namespace c2d
