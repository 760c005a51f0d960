// The confinement of an RC section's core by its stirrups (materials/
// Confinement): the confinement effectiveness and the confined ultimate strain
// against a hand calculation of EN 1998-3 (A.10), (A.11) with EN 1998-1
// 5.4.3.2.2(8)'s alpha, and the mean chord rotation at ultimate against a hand
// evaluation of EN 1998-3 (A.1).
#include <gtest/gtest.h>

#include <cmath>

#include "materials/Confinement.h"
#include "materials/RcSection.h"
#include "tests/unit/RcTestSupport.h"

namespace c2d {
namespace {

using test::v20;

TEST(RcConfinement, EffectivenessAndConfinedStrainByHand) {
  // Core b0 = h0 = 0.4 m (to the bars' centres). s = 0.1 m:
  //   alpha_s = (1 - 0.1/0.8)^2 = 0.765625, alpha_n = 1 - 4 (0.16)/(6 (0.16)) = 1/3,
  //   alpha = 0.2552083; rho_sx = 1.5708e-4/(0.5 x 0.1) = 3.14159e-3;
  //   alpha rho_sx fyw/fc = 0.2552083 x 3.14159e-3 x 500/30 = 0.0133627;
  //   fcc = 30 (1 + 3.7 x 0.0133627^0.86) = 30 x 1.090455 = 32.714 MPa;
  //   eps_cu,c = 0.004 + 0.5 x 0.2552083 x 3.14159e-3 x 500/32.714 = 0.010127.
  const auto c = confinementOf(v20(0.1));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->b0, 0.4, 1e-12);
  EXPECT_NEAR(c->h0, 0.4, 1e-12);
  EXPECT_NEAR(c->alphaS, 0.765625, 1e-9);
  EXPECT_NEAR(c->alphaN, 1.0 / 3, 1e-9);
  EXPECT_NEAR(c->alpha, 0.2552083, 1e-6);
  EXPECT_NEAR(c->rhoSx, 3.14159e-3, 1e-8);
  EXPECT_NEAR(c->fcc, 32.714e3, 2);
  EXPECT_NEAR(c->epsCu, 0.010127, 2e-6);
  // s = 0.3 m: alpha_s = (1 - 0.3/0.8)^2 = 0.390625, alpha = 0.1302083,
  // rho_sx = 1.0472e-3, index 2.27256e-3, fcc = 30 (1 + 3.7 x 0.0053294)
  // = 30.5916 MPa, eps_cu,c = 0.004 + 0.5 x 1.36354e-4 x 500/30.5916 = 0.0051143.
  const auto sparse = confinementOf(v20(0.3));
  ASSERT_TRUE(sparse);
  EXPECT_NEAR(sparse->alpha, 0.1302083, 1e-6);
  EXPECT_NEAR(sparse->fcc, 30.5916e3, 2);
  EXPECT_NEAR(sparse->epsCu, 0.0051143, 2e-6);
  EXPECT_FALSE(confinementOf(v20(0)));  // no links: EC2's eps_cu2
}

TEST(RcConfinement, ChordRotationAtUltimateByHandFromEquationA1) {
  // N = -1000 kN: nu = 1000/(0.25 x 30e3) = 0.13333, 0.3^nu = 0.851693;
  // w = w' = 1.25664e-3 x 500/(0.5 x 0.45 x 30) = 0.093084: [1 x 30]^0.225 =
  // 2.149524; 25^0.0133627 = 1.043951:
  //   theta_um/(L_V/h)^0.35 = 0.016 x 0.851693 x 2.149524 x 1.043951 = 0.030579,
  // and at L_V = 3 m (6^0.35 = 1.872171) theta_um = 0.057249 rad.
  const double hand = 0.016 * std::pow(0.3, 1000 / (0.25 * 30e3)) * std::pow(30.0, 0.225) *
                      std::pow(25.0, 0.2552083 * 3.14159265e-3 * 500 / 30);
  EXPECT_NEAR(hand, 0.030579, 2e-6);
  for (int sign : {1, -1}) {
    const auto f = chordRotationFactor(v20(0.1), -1000, sign);
    ASSERT_TRUE(f);
    EXPECT_NEAR(*f, hand, 1e-6 * hand);
  }
  // Tension counts as nu = 0; an unbalanced section: omega'/omega; units.
  RcSectionData d = v20(0.1);
  EXPECT_NEAR(*chordRotationFactor(d, 500, 1), hand / std::pow(0.3, 1000 / 7.5e3), 1e-6 * hand);
  d.bars[0].area /= 2;  // top bars halved: positive moments compress them
  EXPECT_NEAR(*chordRotationFactor(d, -1000, 1) / *chordRotationFactor(v20(0.1), -1000, 1),
              std::pow(0.5, 0.225), 1e-9);
  d = v20(0.1);
  d.fc = 30;  // MPa: the same rule
  d.fy = 500;
  d.stirrups->fy = 500;
  EXPECT_NEAR(*chordRotationFactor(d, -1000e-3, 1), hand, 1e-6 * hand);
  d.fc = 3e-2;  // no unit system with C30 at that number
  EXPECT_FALSE(chordRotationFactor(d, 0, 1));
}

}  // namespace
}  // namespace c2d
