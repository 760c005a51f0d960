// The infill strut's law (materials/StrutLaw): compression only, elastic to
// the peak, then the residual, then gone; unloading along the secant; a doomed
// strut gone once it carries nothing; a weakened law keeping its share.
#include <gtest/gtest.h>

#include <stdexcept>

#include "materials/StrutLaw.h"

namespace c2d {
namespace {

TEST(StrutLaw, CompressionOnlyElasticToThePeakThenResidualThenGone) {
  const StrutLaw law(1000, 2);  // s_p = 0.002
  const StrutLawState fresh;
  EXPECT_EQ(law.evaluate(0.001, fresh).N, 0.0);  // tension: nothing
  EXPECT_EQ(law.evaluate(0.001, fresh).dN, 0.0);
  const StrutResponse e = law.evaluate(-0.001, fresh);
  EXPECT_DOUBLE_EQ(e.N, -1.0);
  EXPECT_DOUBLE_EQ(e.dN, 1000);
  EXPECT_DOUBLE_EQ(law.evaluate(-0.002, fresh).N, -2.0);  // the peak
  // Softening: from 2 at s_p to 0.4 at 5 s_p, slope -1.6/0.008 = -200.
  const StrutResponse soft = law.evaluate(-0.004, fresh);
  EXPECT_NEAR(soft.N, -(2 - 200 * 0.002), 1e-12);
  EXPECT_NEAR(soft.dN, -200, 1e-9);
  EXPECT_NEAR(law.evaluate(-0.012, fresh).N, -0.4, 1e-12);  // residual 0.2 Pu
  EXPECT_NEAR(law.evaluate(-0.015, fresh).N, -0.4, 1e-12);  // held to 8 s_p
  EXPECT_NEAR(law.evaluate(-0.018, fresh).N, -0.2, 1e-12);  // falls to 0 at 10 s_p
  const StrutResponse gone = law.evaluate(-0.0201, fresh);
  EXPECT_TRUE(gone.state.gone);
  EXPECT_EQ(gone.N, 0.0);
  // Gone is for good, whatever the strain.
  EXPECT_EQ(law.evaluate(-0.001, gone.state).N, 0.0);
}

TEST(StrutLaw, UnloadsAlongTheSecantAndReloadsToTheEnvelope) {
  const StrutLaw law(1000, 2);
  const StrutResponse past = law.evaluate(-0.006, StrutLawState{});  // P = 2 - 200 0.004 = 1.2
  ASSERT_NEAR(past.N, -1.2, 1e-12);
  const StrutResponse back = law.evaluate(-0.003, past.state);
  EXPECT_NEAR(back.N, -0.6, 1e-12);  // secant 1.2/0.006
  EXPECT_NEAR(back.dN, 200, 1e-9);
  EXPECT_NEAR(back.energy, 0.5 * 0.6 * 0.003, 1e-15);
  EXPECT_NEAR(law.evaluate(-0.007, past.state).N, -1.0, 1e-12);  // on the envelope again
}

TEST(StrutLaw, ADoomedStrutGoesOnceItCarriesNothing) {
  const StrutLaw law(1000, 2);
  StrutLawState s;
  s.doomed = true;
  EXPECT_DOUBLE_EQ(law.evaluate(-0.001, s).N, -1.0);  // still compressed: carries on
  EXPECT_TRUE(law.evaluate(0.0001, s).state.gone);
}

TEST(StrutLaw, WeakenedKeepsTheShareOfStiffnessAndStrength) {
  StrutLaw law(1000, 2);
  law.scale(0.25);
  EXPECT_DOUBLE_EQ(law.stiffness(), 250);
  EXPECT_DOUBLE_EQ(law.strength(), 0.5);
  EXPECT_DOUBLE_EQ(law.peakStrain(), 0.002);
  EXPECT_THROW(law.scale(0), std::invalid_argument);
  EXPECT_THROW(law.scale(1.5), std::invalid_argument);
}

}  // namespace
}  // namespace c2d
